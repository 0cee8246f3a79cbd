// Headless OpenGL ES 3 contexts on EGL: no display, no X, no window; rendering goes to
// framebuffer objects only. Mesa's surfaceless platform first (llvmpipe or a GPU), then
// EGL_EXT_platform_device (NVIDIA's headless driver has no surfaceless platform). Contexts of one
// platform share one reference-counted EGL display, so destroying one context never terminates
// the display another is using. Creating a context makes it current on this thread.
#pragma once

#include <memory>

#include "gl/GlContext.h"

namespace toyhost {

enum class EglPlatform {
    Automatic,    // surfaceless when available, else the first EGL device that initialises
    Surfaceless,  // EGL_MESA_platform_surfaceless only
    Device,       // EGL_EXT_platform_device only
};

struct HeadlessOptions {
    EglPlatform platform = EglPlatform::Automatic;
};

Result<std::shared_ptr<GlContext>> createHeadlessContext(const HeadlessOptions& options = {});

// "surfaceless", "device" or "automatic".
const char* eglPlatformName(EglPlatform platform);

// The platform the environment asks for (TOYHOST_EGL_PLATFORM: surfaceless, device or automatic;
// unset or empty: automatic), the one place every headless context's choice is read from: the
// CLI, the compatibility runner and the library (so Python too). A usage error names the variable.
Result<EglPlatform> eglPlatformFromEnvironment();

}  // namespace toyhost
