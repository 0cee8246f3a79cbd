#include "gl/HeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <vector>

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

Error eglFailure(const std::string& what) { return Error("EGL: " + what + ": " + eglErrorName(eglGetError()), Code::GlEgl); }

bool hasToken(const char* list, const char* token) {
    if (!list) return false;
    const size_t n = std::strlen(token);
    for (const char* p = list; (p = std::strstr(p, token)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// An initialised EGL display shared by every context made on it; eglTerminate runs when the
// last owner lets go. EGL returns the same EGLDisplay handle for the same platform and native
// display, and eglTerminate on it would pull it from under every other context, hence the count.
class EglDisplay {
public:
    EglDisplay(EGLDisplay display, std::string platform) : display_(display), platform_(std::move(platform)) {}
    ~EglDisplay() { eglTerminate(display_); }
    EglDisplay(const EglDisplay&) = delete;
    EglDisplay& operator=(const EglDisplay&) = delete;
    EGLDisplay get() const { return display_; }
    const std::string& platform() const { return platform_; }

private:
    EGLDisplay display_;
    std::string platform_;
};

// Displays by handle, so that two contexts on one platform share one EglDisplay.
std::mutex displaysMutex;
std::map<EGLDisplay, std::weak_ptr<EglDisplay>>& displays() {
    static std::map<EGLDisplay, std::weak_ptr<EglDisplay>> all;
    return all;
}

Result<std::shared_ptr<EglDisplay>> shareDisplay(EGLDisplay handle, const std::string& platform) {
    std::lock_guard lock(displaysMutex);
    if (auto it = displays().find(handle); it != displays().end())
        if (std::shared_ptr<EglDisplay> shared = it->second.lock()) return shared;
    if (!eglInitialize(handle, nullptr, nullptr)) return eglFailure("Failed to initialize the " + platform + " display");
    auto shared = std::make_shared<EglDisplay>(handle, platform);
    displays()[handle] = shared;
    return shared;
}

Result<std::shared_ptr<EglDisplay>> surfacelessDisplay() {
    if (!hasToken(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
        return Error("EGL: the surfaceless platform (EGL_MESA_platform_surfaceless) is not available", Code::GlEgl);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return Error("EGL: eglGetPlatformDisplayEXT is missing", Code::GlEgl);
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) return eglFailure("Failed to get the surfaceless display");
    return shareDisplay(display, "surfaceless");
}

// The first EGL device whose display initialises (NVIDIA's headless driver, or Mesa's devices).
Result<std::shared_ptr<EglDisplay>> deviceDisplay() {
    // The functions are asked for, not the client extension string: with glvnd's libEGL and
    // NVIDIA's driver (an H100, driver 580) the string lacked EGL_EXT_platform_device although
    // eglQueryDevicesEXT listed the GPU and its display initialised.
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!queryDevices || !getPlatformDisplay)
        return Error("EGL: the device platform (EGL_EXT_platform_device) is not available", Code::GlEgl);
    EGLint count = 0;
    if (!queryDevices(0, nullptr, &count) || count <= 0) return Error("EGL: no EGL devices found", Code::GlEgl);
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    if (!queryDevices(count, devices.data(), &count)) return eglFailure("Failed to list EGL devices");
    std::string tried;
    for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)], nullptr);
        if (display == EGL_NO_DISPLAY) continue;
        Result<std::shared_ptr<EglDisplay>> shared = shareDisplay(display, "device " + std::to_string(i));
        if (shared) return shared;
        tried += (tried.empty() ? "" : "; ") + shared.error().first().message;
    }
    return Error("EGL: none of the " + std::to_string(count) + " EGL devices initialised" +
                     (tried.empty() ? std::string() : " (" + tried + ")"),
                 Code::GlEgl);
}

class HeadlessContext final : public GlContext {
public:
    HeadlessContext(std::shared_ptr<EglDisplay> display, EGLContext context)
        : display_(std::move(display)), context_(context) {}
    ~HeadlessContext() override {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_->get(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_->get(), context_);
    }

    Status makeCurrent() override {
        if (!eglMakeCurrent(display_->get(), EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            return eglFailure("Failed to make context current");
        return okStatus();
    }
    void* procAddress(const char* name) const override {
        return reinterpret_cast<void*>(eglGetProcAddress(name));
    }
    std::string describe() const override {
        auto str = [](GLenum name) {
            const char* s = reinterpret_cast<const char*>(glGetString(name));
            return std::string(s ? s : "?");
        };
        return "EGL " + display_->platform() + "; " + str(GL_VERSION) + "; " + str(GL_RENDERER);
    }

private:
    std::shared_ptr<EglDisplay> display_;  // outlives the context: destroyed after it
    EGLContext context_;
};

Result<std::shared_ptr<GlContext>> contextOn(std::shared_ptr<EglDisplay> display) {
    EGLDisplay handle = display->get();
    if (!hasToken(eglQueryString(handle, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        return Error("EGL: EGL_KHR_surfaceless_context is not supported on the " + display->platform() + " display",
                     Code::GlEgl);
    if (!eglBindAPI(EGL_OPENGL_ES_API)) return eglFailure("Failed to bind the OpenGL ES API");
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    if (!eglChooseConfig(handle, configAttribs, &config, 1, &configCount) || configCount == 0)
        return eglFailure("No OpenGL ES 3 config");
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext context = eglCreateContext(handle, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) return eglFailure("Failed to create an OpenGL ES 3 context");
    auto made = std::make_shared<HeadlessContext>(std::move(display), context);
    if (Status current = made->makeCurrent(); !current) return current.error();
    return std::shared_ptr<GlContext>(std::move(made));
}

}  // namespace

const char* eglPlatformName(EglPlatform platform) {
    switch (platform) {
        case EglPlatform::Surfaceless: return "surfaceless";
        case EglPlatform::Device: return "device";
        case EglPlatform::Automatic: break;
    }
    return "automatic";
}

Result<EglPlatform> eglPlatformFromEnvironment() {
    const char* platform = std::getenv("TOYHOST_EGL_PLATFORM");
    if (!platform || !*platform) return EglPlatform::Automatic;
    const std::string name = platform;
    if (name == "device") return EglPlatform::Device;
    if (name == "surfaceless") return EglPlatform::Surfaceless;
    if (name == "automatic") return EglPlatform::Automatic;
    return Error("TOYHOST_EGL_PLATFORM=" + name + ": expected surfaceless, device or automatic", Code::Usage);
}

Result<std::shared_ptr<GlContext>> createHeadlessContext(const HeadlessOptions& options) {
    Result<std::shared_ptr<EglDisplay>> display = Error("unreachable");
    switch (options.platform) {
        case EglPlatform::Surfaceless: display = surfacelessDisplay(); break;
        case EglPlatform::Device: display = deviceDisplay(); break;
        case EglPlatform::Automatic: {
            display = surfacelessDisplay();
            if (!display) {
                Result<std::shared_ptr<EglDisplay>> device = deviceDisplay();
                if (!device)
                    return Error("EGL: no headless platform: " + display.error().first().message + "; " +
                                     device.error().first().message + " (install Mesa's EGL, libegl-mesa0, or a GPU driver's EGL)",
                                 Code::GlEgl);
                display = std::move(device);
            }
            break;
        }
    }
    if (!display) return display.error();
    return contextOn(std::move(*display));
}

}  // namespace toyhost
