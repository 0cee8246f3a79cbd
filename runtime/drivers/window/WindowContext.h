// WindowContext: an OpenGL ES 3 context in a GLFW window, the backend of window mode. It is both
// the GlContext (make current, proc addresses) and the GlSurface (framebuffer size in pixels,
// present, swap interval). EGL is asked for first (Mesa under X or Xvfb, Wayland), then the
// platform's native API (GLX). Event handling stays with the driver, which installs GLFW
// callbacks on handle(). One process may hold several windows; GLFW is initialised with the
// first and terminated with the last.
#pragma once

#include <memory>
#include <string>

#include "gl/GlContext.h"

struct GLFWwindow;

namespace toyhost {

struct WindowOptions {
    int width = 0;   // window size in screen coordinates (framebuffer pixels differ on HiDPI)
    int height = 0;
    std::string title = "toyhost";
    bool visible = true;
};

class WindowContext final : public GlContext, public GlSurface {
public:
    // Opens the window and makes its context current on this thread. Fails with a message that
    // says what to do when there is no display.
    static Result<std::shared_ptr<WindowContext>> create(const WindowOptions& options);
    ~WindowContext() override;

    // GlContext
    Status makeCurrent() override;
    // The context is no longer current on this thread (so that another thread can make it current).
    void releaseCurrent();
    void* procAddress(const char* name) const override;
    std::string describe() const override;
    GlSurface* surface() override { return this; }

    // GlSurface
    Size framebufferSize() const override;
    Status present() override;
    Status setSwapInterval(int interval) override;

    GLFWwindow* handle() const { return window_; }
    Size windowSize() const;
    void setTitle(const std::string& title);
    bool closeRequested() const;
    void requestClose();
    // Switches between the window and full screen on the primary monitor.
    void toggleFullscreen();
    bool fullscreen() const { return fullscreen_; }

private:
    WindowContext() = default;
    GLFWwindow* window_ = nullptr;
    std::string api_;  // "EGL" or "native"
    bool fullscreen_ = false;
    int savedX_ = 0, savedY_ = 0, savedW_ = 0, savedH_ = 0;
};

// True when a window can probably be opened ($DISPLAY or $WAYLAND_DISPLAY set); the CLI's
// default mode follows it.
bool displayAvailable();

}  // namespace toyhost
