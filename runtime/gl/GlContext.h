// GlContext and GlSurface: the small interfaces every GL backend fills. A context is what every
// backend has (make current, look up GL functions, describe itself); a surface is what only a
// window has (framebuffer size in pixels, present, swap interval). The renderer needs a current
// OpenGL ES 3 context and never learns which backend made it. Backends: headless EGL
// (gl/HeadlessContext.h) and a GLFW window (gl/WindowContext.h).
#pragma once

#include <string>

#include "core/Result.h"
#include "gl/GpuActivity.h"

namespace toyhost {

class GlSurface {
public:
    virtual ~GlSurface() = default;
    struct Size {
        int width = 0;
        int height = 0;
    };
    // The default framebuffer's size in pixels (not window coordinates: HiDPI differs).
    virtual Size framebufferSize() const = 0;
    // Shows what was drawn to the default framebuffer (swap buffers).
    virtual Status present() = 0;
    // 1: wait for vertical sync when presenting; 0: do not.
    virtual Status setSwapInterval(int interval) = 0;
};

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    virtual Status makeCurrent() = 0;
    // The address of a GL or GL extension function, or null.
    virtual void* procAddress(const char* name) const = 0;
    // One line naming the backend, API version and renderer, for logs and benchmarks.
    virtual std::string describe() const = 0;
    // The on-screen surface of a window backend; null for headless contexts.
    virtual GlSurface* surface() { return nullptr; }
    // What this context's GPU work is, for a watchdog (gl/GpuActivity.h): the one place every
    // renderer, readback and wait on this context publishes to.
    GpuActivity& gpuActivity() { return gpuActivity_; }

private:
    GpuActivity gpuActivity_;
};

// Checks the GL extensions Shadertoy's WebGL2 player relies on (float render targets and
// linear filtering of float textures). Needs a current context.
Status checkRequiredGlFeatures();

// "GL_INVALID_OPERATION" etc., for error messages.
const char* glErrorName(unsigned int error);

// GL_MAX_TEXTURE_SIZE of the current context.
int maxTextureSize();

}  // namespace toyhost
