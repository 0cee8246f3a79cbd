// GlContext: the small interface every GL backend fills (make current, present, describe).
// The renderer only needs a current OpenGL ES 3 context and never knows which backend made it.
// Backends: headless EGL surfaceless (EglSurfacelessContext.h); a window backend comes later.
#pragma once

#include <memory>
#include <string>

#include "core/Result.h"

namespace toyhost {

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    virtual Status makeCurrent() = 0;
    // True when the context has an on-screen surface to present to (window backends).
    virtual bool hasSurface() const = 0;
    // Shows the default framebuffer (swap); a no-op for headless contexts.
    virtual Status present() = 0;
    // One line naming the backend, API version and renderer, for logs and benchmarks.
    virtual std::string describe() const = 0;
};

// Checks the GL extensions Shadertoy's WebGL2 player relies on (float render targets and
// linear filtering of float textures). Needs a current context.
Status checkRequiredGlFeatures();

// "GL_INVALID_OPERATION" etc., for error messages.
const char* glErrorName(unsigned int error);

}  // namespace toyhost
