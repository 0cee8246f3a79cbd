// Headless OpenGL ES 3 context on EGL's Mesa surfaceless platform: no display, no X, no window.
// Rendering goes to framebuffer objects only. Creating it makes it current on this thread.
#pragma once

#include <memory>

#include "gl/GlContext.h"

namespace toyhost {

Result<std::unique_ptr<GlContext>> createEglSurfacelessContext();

}  // namespace toyhost
