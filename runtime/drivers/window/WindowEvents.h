// WindowEvents: the window's two threads meet here. GLFW must handle events on the thread that
// opened the window (the main thread), and the shadertoy renders on the GL thread, so a long frame
// never keeps the window from answering: Esc or the close button are seen at once (and the stop's
// grace period starts), the window can be moved, and input is queued for the next frame. The main
// thread pumps events (GLFW callbacks become the same InputEvents the scripts make: iMouse in
// canvas pixels as the site computes it, keys as JavaScript keyCodes, auto-repeat ignored) and
// applies what only it may do (title, full screen); the GL thread takes events and controls and
// says what the title and canvas are, and reads the pointer for the overlay (which owns the mouse
// while the inspector is open). Needs no GL context.
#pragma once

#include <array>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "drivers/window/WindowContext.h"
#include "input/InputEvent.h"
#include "input/WindowControls.h"
#include "timing/WindowTitle.h"

namespace toyhost {

class WindowEvents {
public:
    // Installs the GLFW callbacks on `window` (main thread). `onQuit` is called on the main thread
    // each time the user closes the window (Esc, Ctrl+Q, the close button): the first asks the run
    // to stop, a second while it stops asks for at once.
    WindowEvents(WindowContext& window, std::function<void()> onQuit);
    ~WindowEvents();
    WindowEvents(const WindowEvents&) = delete;
    WindowEvents& operator=(const WindowEvents&) = delete;

    // Main thread: waits up to `seconds` for events and handles them, then applies the title.
    void pump(double seconds);
    // Any thread: makes pump() return now.
    void wake();

    // GL thread.
    // Moves the input events queued since the last call (in order) to the end of `out`.
    void takeEvents(std::vector<InputEvent>& out);
    bool hasEvents();
    // True once for each press of `control` since the last call.
    bool takeControl(Control control);
    bool quitRequested();
    GlSurface::Size framebufferSize();
    // The canvas size (for the mouse position) and the window title to show (once the user asked
    // to close, the main thread shows it as stopping).
    void setCanvasSize(int width, int height);
    void setTitle(WindowTitle title);
    // Waits until an event comes in or `seconds` pass.
    void waitForInput(double seconds);

    // The pointer as the overlay sees it (drivers/window/Overlay.h): framebuffer pixels, top-left
    // origin; `down` also reads true once after a press released before this call, so that a
    // quick click is never lost between two frames.
    struct Pointer {
        float x = -1, y = -1;
        bool down = false;
    };
    Pointer takePointer();
    // While captured, presses (and the drags they start) are the overlay's and never reach the
    // shader's iMouse; a drag the shader already holds ends as it began.
    void setPointerCaptured(bool captured);

private:
    friend struct WindowCallbacks;
    void push(const InputEvent& event);  // with the lock held
    void trackPointer(double cursorX, double cursorY);  // with the lock held
    glm::vec2 canvasPosition(double cursorX, double cursorY) const;

    WindowContext& window_;
    std::function<void()> onQuit_;
    std::mutex mutex_;
    std::condition_variable input_;
    std::vector<InputEvent> events_;
    std::array<bool, kControlCount> controls_{};  // by Control
    int buttonsDown_ = 0;
    int overlayButtonsDown_ = 0;
    bool overlayPressed_ = false;  // since the last takePointer()
    bool pointerCaptured_ = false;
    float pointerX_ = -1, pointerY_ = -1;
    bool quit_ = false;
    int canvasW_ = 1, canvasH_ = 1;
    GlSurface::Size framebuffer_, windowSize_;
    WindowTitle title_;
    bool titleSet_ = false;
    std::string shownTitle_;
};

}  // namespace toyhost
