// FramePacer: when a run with a fixed step (--fps F) may draw its next frame: F frames per second
// of wall time, so a window previews the recording's timing (iTime advances 1/F per frame and now
// also 1/F per second), and a headless run with --paced feeds a live consumer at its rate. Pure
// arithmetic on the monotonic times passed in; no GL, no sleeping (the drivers wait). Tested with a
// made-up clock in tests/unit/test_frame_pacer.cpp.
#pragma once

#include <chrono>

namespace toyhost {

// The monotonic clock the drivers pass to a FramePacer, in seconds.
inline double monotonicNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class FramePacer {
public:
    explicit FramePacer(double fps) : period_(1.0 / fps) {}

    // Seconds to wait at monotonic time `now` before the next frame is due; 0: draw it now.
    double wait(double now) const { return started_ && due_ > now ? due_ - now : 0.0; }
    // A frame was drawn at `now` (call when wait() said 0). The next is due one period after this
    // one was due, so the rate holds on average even when the waits overshoot; a frame that is
    // late by more than one period (a slow frame, a busy machine) restarts the schedule at `now`
    // rather than drawing a burst of frames to catch up.
    void drawn(double now) {
        if (!started_ || now - due_ > period_) due_ = now;
        due_ += period_;
        started_ = true;
    }
    // After a pause or a restart: the next frame is due at once, with no catching up.
    void reset() { started_ = false; }

private:
    double period_;
    double due_ = 0;
    bool started_ = false;
};

}  // namespace toyhost
