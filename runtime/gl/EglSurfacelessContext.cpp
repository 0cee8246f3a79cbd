#include "gl/EglSurfacelessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <cstring>
#include <string>

namespace toyhost {

namespace {

const char* eglErrorName(EGLint error) {
    switch (error) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    }
    return "unknown EGL error";
}

Error eglFailure(const std::string& what) {
    return Error{"EGL: " + what + ": " + eglErrorName(eglGetError())};
}

bool hasToken(const char* list, const char* token) {
    if (!list) return false;
    const size_t n = std::strlen(token);
    for (const char* p = list; (p = std::strstr(p, token)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

class EglSurfacelessContext final : public GlContext {
public:
    EglSurfacelessContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
    ~EglSurfacelessContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }

    Status makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            return eglFailure("Failed to make context current");
        return okStatus();
    }
    bool hasSurface() const override { return false; }
    Status present() override { return okStatus(); }
    std::string describe() const override {
        auto str = [](GLenum name) {
            const char* s = reinterpret_cast<const char*>(glGetString(name));
            return std::string(s ? s : "?");
        };
        return "EGL surfaceless; " + str(GL_VERSION) + "; " + str(GL_RENDERER);
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

}  // namespace

Result<std::unique_ptr<GlContext>> createEglSurfacelessContext() {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasToken(clientExtensions, "EGL_MESA_platform_surfaceless"))
        return Error{"EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) is not "
                     "available; install Mesa's EGL (libegl-mesa0)"};
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return Error{"EGL: eglGetPlatformDisplayEXT is missing"};

    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) return eglFailure("Failed to get the surfaceless display");
    if (!eglInitialize(display, nullptr, nullptr)) return eglFailure("Failed to initialize");

    auto fail = [&](const std::string& what) {
        Error error = eglFailure(what);
        eglTerminate(display);
        return error;
    };
    if (!hasToken(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        return fail("EGL_KHR_surfaceless_context is not supported");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail("Failed to bind the OpenGL ES API");

    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0,
                                    EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &configCount) || configCount == 0)
        return fail("No OpenGL ES 3 config");

    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return fail("Failed to create an OpenGL ES 3 context");

    auto result = std::make_unique<EglSurfacelessContext>(display, context);
    if (Status current = result->makeCurrent(); !current) return current.error();
    return std::unique_ptr<GlContext>(std::move(result));
}

}  // namespace toyhost
