// RealTimeClock: the clock of an interactive (window) run. In real time, iTime follows a monotonic
// clock from the start (minus the time spent paused), iTimeDelta is the measured time between two
// rendered frames, iFrameRate a smoothed 1/iTimeDelta and iDate the live local wall clock. With a
// fixed step (--fps F) every rendered frame advances iTime by exactly 1/F, as headless runs do,
// whatever the display rate. Pause stops iTime (no frame is rendered while paused, as on the
// site); stepOnce() lets exactly one frame through. Restart puts iTime back at the start.
// The caller passes the monotonic time and the wall clock, so this is pure arithmetic (no GL, no
// system calls) and tests drive it with made-up times.
#pragma once

#include <optional>

#include "timing/FrameTime.h"

namespace toyhost {

struct RealTimeClockOptions {
    std::optional<double> fixedFps;  // set: fixed step of 1/fps per rendered frame
    double startTime = 0;            // iTime of the first frame (and after a restart)
    // The iTimeDelta of a frame that has no previous one (the first, and after a restart or a
    // pause), and the starting value of the smoothed frame rate.
    double nominalFps = 60;
};

class RealTimeClock {
public:
    // `now`: monotonic seconds (any origin) at the start of the run.
    RealTimeClock(const RealTimeClockOptions& options, double now);

    // True when a frame should be rendered now (not paused, or a single step was asked for).
    bool shouldRender() const { return !paused_ || stepPending_; }
    // The time of the frame about to be rendered at monotonic time `now`, with iDate taken from
    // `wallClock` (localWallClockNow's form). Call once per rendered frame.
    FrameTime frame(double now, double wallClock);

    void setPaused(bool paused, double now);
    bool paused() const { return paused_; }
    // While paused: the next frame() renders one frame (at time + one step), then stays paused.
    void stepOnce() { stepPending_ = paused_; }
    // iTime back to the start; the next frame has the nominal iTimeDelta.
    void restart(double now);

    double time() const { return lastTime_; }         // iTime of the last frame rendered
    double frameRate() const { return frameRate_; }   // the smoothed rate of the last frame

private:
    RealTimeClockOptions options_;
    double origin_;             // monotonic time that maps to startTime
    double pausedSince_ = 0;    // when paused: monotonic time of the pause
    bool paused_ = false;
    bool stepPending_ = false;
    bool fresh_ = true;         // the next frame has no previous one to measure against
    long framesSinceRestart_ = 0;
    double lastTime_;
    double frameRate_;
};

}  // namespace toyhost
