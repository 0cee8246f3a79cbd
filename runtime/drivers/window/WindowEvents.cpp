#include "drivers/window/WindowEvents.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>

#include "input/WindowInput.h"
#include "render/Present.h"

namespace toyhost {

// GLFW's callbacks, on the main thread inside pump().
struct WindowCallbacks {
    static WindowEvents& of(GLFWwindow* window) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(window)); }

    static void cursor(GLFWwindow* window, double x, double y) {
        WindowEvents& e = of(window);
        std::lock_guard lock(e.mutex_);
        e.trackPointer(x, y);
        if (e.buttonsDown_ == 0) return;  // iMouse.xy moves only while the button is held
        const glm::vec2 p = e.canvasPosition(x, y);
        e.push(InputEvent::mouseMove(p.x, p.y));
    }

    static void button(GLFWwindow* window, int, int action, int) {
        WindowEvents& e = of(window);
        double x = 0, y = 0;
        glfwGetCursorPos(window, &x, &y);
        std::lock_guard lock(e.mutex_);
        e.trackPointer(x, y);
        if (action == GLFW_PRESS && e.pointerCaptured_ && e.buttonsDown_ == 0) {
            ++e.overlayButtonsDown_;
            e.overlayPressed_ = true;
            e.input_.notify_all();
            return;
        }
        if (action == GLFW_RELEASE && e.overlayButtonsDown_ > 0) {
            --e.overlayButtonsDown_;
            e.input_.notify_all();
            return;
        }
        if (action == GLFW_PRESS) {
            if (e.buttonsDown_++ == 0) {
                const glm::vec2 p = e.canvasPosition(x, y);
                e.push(InputEvent::mouseDown(p.x, p.y));
            }
        } else if (action == GLFW_RELEASE && e.buttonsDown_ > 0) {
            if (--e.buttonsDown_ == 0) e.push(InputEvent::mouseUp());
        }
    }

    static void key(GLFWwindow* window, int key, int, int action, int mods) {
        if (action == GLFW_REPEAT) return;  // the site ignores auto-repeat
        WindowEvents& e = of(window);
        const Control control = controlForKey(key, mods);
        if (control == Control::Quit && action == GLFW_PRESS) {
            glfwSetWindowShouldClose(window, GLFW_TRUE);  // seen at the end of pump()
            return;
        }
        if (control == Control::Fullscreen && action == GLFW_PRESS) {
            e.window_.toggleFullscreen();  // main thread only
            return;
        }
        std::lock_guard lock(e.mutex_);
        if (control != Control::None) {
            if (action == GLFW_PRESS) e.controls_[static_cast<int>(control)] = true;
            e.input_.notify_all();
            return;
        }
        const int code = javascriptKeyCode(key);
        if (code == 0) return;
        e.push(action == GLFW_PRESS ? InputEvent::keyDown(code) : InputEvent::keyUp(code));
    }
};

WindowEvents::WindowEvents(WindowContext& window, std::function<void()> onQuit)
    : window_(window), onQuit_(std::move(onQuit)) {
    framebuffer_ = window_.framebufferSize();
    windowSize_ = window_.windowSize();
    glfwSetWindowUserPointer(window_.handle(), this);
    glfwSetCursorPosCallback(window_.handle(), WindowCallbacks::cursor);
    glfwSetMouseButtonCallback(window_.handle(), WindowCallbacks::button);
    glfwSetKeyCallback(window_.handle(), WindowCallbacks::key);
}

WindowEvents::~WindowEvents() {
    glfwSetCursorPosCallback(window_.handle(), nullptr);
    glfwSetMouseButtonCallback(window_.handle(), nullptr);
    glfwSetKeyCallback(window_.handle(), nullptr);
    glfwSetWindowUserPointer(window_.handle(), nullptr);
}

void WindowEvents::push(const InputEvent& event) {
    // Moves between two frames: only the last position matters (and the queue stays small while
    // paused).
    if (event.type == InputEvent::Type::MouseMove && !events_.empty() &&
        events_.back().type == InputEvent::Type::MouseMove) {
        events_.back() = event;
    } else {
        events_.push_back(event);
    }
    input_.notify_all();
}

void WindowEvents::trackPointer(double cursorX, double cursorY) {
    if (windowSize_.width <= 0 || windowSize_.height <= 0) return;
    pointerX_ = static_cast<float>(cursorX * framebuffer_.width / windowSize_.width);
    pointerY_ = static_cast<float>(cursorY * framebuffer_.height / windowSize_.height);
}

glm::vec2 WindowEvents::canvasPosition(double cx, double cy) const {
    // The cursor (window coordinates, top-left origin) in canvas pixels as the site computes them,
    // taking the canvas's place in the framebuffer into account.
    const GlSurface::Size win = windowSize_, fb = framebuffer_;
    if (win.width <= 0 || win.height <= 0 || fb.width <= 0 || fb.height <= 0) return glm::vec2(0.0f);
    const PresentRect r = presentRect(canvasW_, canvasH_, fb.width, fb.height);
    const double fx = cx * fb.width / win.width;
    const double fyTop = cy * fb.height / win.height;
    const double localYTop = fyTop - (fb.height - r.y - r.height);
    return siteMousePosition(fx - r.x, localYTop, r.width, r.height, canvasW_, canvasH_);
}

void WindowEvents::pump(double seconds) {
    glfwWaitEventsTimeout(seconds);
    const GlSurface::Size fb = window_.framebufferSize(), win = window_.windowSize();
    bool quitNow = false;
    std::string title;
    {
        std::lock_guard lock(mutex_);
        framebuffer_ = fb;
        windowSize_ = win;
        if (window_.closeRequested()) {
            quit_ = quitNow = true;
            glfwSetWindowShouldClose(window_.handle(), GLFW_FALSE);  // so that a second Esc or click is seen
        }
        if (titleSet_ || quit_) {
            WindowTitle shown = title_;
            shown.stopping = quit_;
            if (std::string text = formatWindowTitle(shown); text != shownTitle_) title = shownTitle_ = std::move(text);
        }
    }
    if (!title.empty()) window_.setTitle(title);
    if (quitNow) {
        if (onQuit_) onQuit_();
        input_.notify_all();
    }
}

void WindowEvents::wake() { glfwPostEmptyEvent(); }

void WindowEvents::takeEvents(std::vector<InputEvent>& out) {
    std::lock_guard lock(mutex_);
    out.insert(out.end(), events_.begin(), events_.end());
    events_.clear();
}

bool WindowEvents::hasEvents() {
    std::lock_guard lock(mutex_);
    return !events_.empty();
}

bool WindowEvents::takeControl(Control control) {
    std::lock_guard lock(mutex_);
    return std::exchange(controls_[static_cast<int>(control)], false);
}

bool WindowEvents::quitRequested() {
    std::lock_guard lock(mutex_);
    return quit_;
}

GlSurface::Size WindowEvents::framebufferSize() {
    std::lock_guard lock(mutex_);
    return framebuffer_;
}

void WindowEvents::setCanvasSize(int width, int height) {
    std::lock_guard lock(mutex_);
    canvasW_ = width;
    canvasH_ = height;
}

void WindowEvents::setTitle(WindowTitle title) {
    {
        std::lock_guard lock(mutex_);
        if (titleSet_ && title == title_) return;
        title_ = std::move(title);
        titleSet_ = true;
    }
    wake();
}

WindowEvents::Pointer WindowEvents::takePointer() {
    std::lock_guard lock(mutex_);
    Pointer p{pointerX_, pointerY_, overlayButtonsDown_ > 0 || overlayPressed_};
    overlayPressed_ = false;
    return p;
}

void WindowEvents::setPointerCaptured(bool captured) {
    std::lock_guard lock(mutex_);
    pointerCaptured_ = captured;
}

void WindowEvents::waitForInput(double seconds) {
    std::unique_lock lock(mutex_);
    input_.wait_for(lock, std::chrono::duration<double>(seconds), [&] {
        if (quit_ || !events_.empty()) return true;
        for (bool pressed : controls_)
            if (pressed) return true;
        return false;
    });
}

}  // namespace toyhost
