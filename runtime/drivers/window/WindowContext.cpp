#include "drivers/window/WindowContext.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <GLES3/gl3.h>

#include <cstdlib>
#include <mutex>

namespace toyhost {

namespace {

std::mutex glfwMutex;
int glfwUsers = 0;          // windows alive; GLFW is terminated with the last one
std::string lastGlfwError;  // set by the error callback (GLFW calls it on the calling thread)

void onGlfwError(int code, const char* description) {
    lastGlfwError = std::string(description ? description : "unknown error") + " (GLFW error 0x" +
                    [&] {
                        char hex[16];
                        std::snprintf(hex, sizeof hex, "%X", static_cast<unsigned>(code));
                        return std::string(hex);
                    }() +
                    ")";
}

Status acquireGlfw() {
    std::lock_guard lock(glfwMutex);
    if (glfwUsers == 0) {
        glfwSetErrorCallback(onGlfwError);
        if (!glfwInit())
            return Error("cannot open a window: " + lastGlfwError +
                             (displayAvailable() ? "" : "; no $DISPLAY or $WAYLAND_DISPLAY is set: use --headless"),
                         Code::WindowInit);
    }
    ++glfwUsers;
    return okStatus();
}

void releaseGlfw() {
    std::lock_guard lock(glfwMutex);
    if (--glfwUsers == 0) glfwTerminate();
}

GLFWwindow* openWindow(const WindowOptions& options, int creationApi) {
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, creationApi);
    glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
    return glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
}

}  // namespace

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

Result<std::shared_ptr<WindowContext>> WindowContext::create(const WindowOptions& options) {
    if (options.width <= 0 || options.height <= 0) return Error("window size must be positive", Code::Internal);
    if (Status glfw = acquireGlfw(); !glfw) return glfw.error();
    std::shared_ptr<WindowContext> context(new WindowContext());
    context->window_ = openWindow(options, GLFW_EGL_CONTEXT_API);
    context->api_ = "EGL";
    if (!context->window_) {
        const std::string eglError = lastGlfwError;
        context->window_ = openWindow(options, GLFW_NATIVE_CONTEXT_API);
        context->api_ = "native";
        if (!context->window_) {
            releaseGlfw();
            return Error("cannot open an OpenGL ES 3 window: " + eglError + "; native: " + lastGlfwError, Code::WindowCreate);
        }
    }
    glfwMakeContextCurrent(context->window_);
    if (Status features = checkRequiredGlFeatures(); !features) return features.error();
    return context;
}

WindowContext::~WindowContext() {
    if (!window_) return;
    glfwDestroyWindow(window_);
    releaseGlfw();
}

Status WindowContext::makeCurrent() {
    glfwMakeContextCurrent(window_);
    return okStatus();
}

void WindowContext::releaseCurrent() { glfwMakeContextCurrent(nullptr); }

void* WindowContext::procAddress(const char* name) const {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
}

std::string WindowContext::describe() const {
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return std::string("GLFW window (") + api_ + "), " + (version ? version : "?") + ", " + (renderer ? renderer : "?");
}

GlSurface::Size WindowContext::framebufferSize() const {
    Size size;
    glfwGetFramebufferSize(window_, &size.width, &size.height);
    return size;
}

GlSurface::Size WindowContext::windowSize() const {
    Size size;
    glfwGetWindowSize(window_, &size.width, &size.height);
    return size;
}

Status WindowContext::present() {
    glfwSwapBuffers(window_);
    return okStatus();
}

Status WindowContext::setSwapInterval(int interval) {
    glfwSwapInterval(interval);
    return okStatus();
}

void WindowContext::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

bool WindowContext::closeRequested() const { return glfwWindowShouldClose(window_) != 0; }

void WindowContext::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void WindowContext::toggleFullscreen() {
    if (!fullscreen_) {
        GLFWmonitor* monitor = glfwGetPrimaryMonitor();
        const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
        if (!mode) return;
        glfwGetWindowPos(window_, &savedX_, &savedY_);
        glfwGetWindowSize(window_, &savedW_, &savedH_);
        glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
        fullscreen_ = true;
    } else {
        glfwSetWindowMonitor(window_, nullptr, savedX_, savedY_, savedW_, savedH_, 0);
        fullscreen_ = false;
    }
}

}  // namespace toyhost
