// RealTimeClock: the clock of an interactive (window) run. In real time, iTime follows a monotonic
// clock from the start (minus the time spent paused), iTimeDelta is the measured time between two
// rendered frames, iFrameRate the site's frame counter (timing/SiteFrameRate.h) and iDate the live
// local wall clock. With a fixed step (--fps F) every rendered frame advances iTime by exactly 1/F,
// as headless runs do, whatever the display rate. Pause stops iTime: no frame is rendered while
// paused, except that, as on the site, input while paused and a restart force one frame at the
// paused time (iTimeDelta 1/60); stepOnce() lets exactly one frame through, one step later.
// repaint() gives the shown frame's time again, for painting it anew (a recompile while paused).
// Restart puts iTime back at the start.
// The caller passes the monotonic time and the wall clock, so this is pure arithmetic (no GL, no
// system calls) and tests drive it with made-up times.
#pragma once

#include <optional>

#include "core/Defaults.h"
#include "timing/FrameTime.h"
#include "timing/SiteFrameRate.h"

namespace toyhost {

struct RealTimeClockOptions {
    std::optional<double> fixedFps;  // set: fixed step of 1/fps per rendered frame
    double startTime = 0;            // iTime of the first frame (and after a restart)
    // The iTimeDelta of a frame that has no previous one (the first, and after a restart or a
    // pause) and of a frame forced while paused.
    double nominalFps = 1.0 / defaults::kRestartTimeDelta;
    // Set (--fps or --date): iDate follows iTime from this wall clock at startTime, by the fixed
    // step's rule (dateOfTime); else iDate is the live wall clock of each frame.
    std::optional<double> wallClockStart;
};

class RealTimeClock {
public:
    // `now`: monotonic seconds (any origin) at the start of the run.
    RealTimeClock(const RealTimeClockOptions& options, double now);

    // True when a frame should be rendered now (not paused, or a step or a forced frame is due).
    bool shouldRender() const { return !paused_ || stepPending_ || forcePending_; }
    // The time of the frame about to be rendered at monotonic time `now`, with iDate taken from
    // `wallClock` (localWallClockNow's form). Call once per rendered frame.
    FrameTime frame(double now, double wallClock);

    void setPaused(bool paused, double now);
    bool paused() const { return paused_; }
    // While paused: the next frame() renders one frame (at time + one step), then stays paused.
    void stepOnce() { stepPending_ = paused_; }
    // While paused: the next frame() renders one frame at the paused time, as the site does when
    // the mouse or a key is used, or the shader restarted, while paused.
    void forceFrame() { forcePending_ = paused_; }
    // The time of the shown frame painted again at monotonic time `now` (a paused window after a
    // recompile, drivers/window): the paused time with iTimeDelta 1/60, as the site paints a frame
    // forced while paused, and counted by the site's frame counter as every painted frame. Pending
    // steps and forced frames stay pending; the clock does not move.
    FrameTime repaint(double now, double wallClock);
    // iTime back to the start; the next frame has the nominal iTimeDelta.
    void restart(double now);

    double time() const { return lastTime_; }  // iTime of the last frame rendered
    // The frame rate measured by the site's counter (frames over each window of > 0.5 s of real
    // time); measuredFrameRate() is empty until the first window closed.
    std::optional<double> measuredFrameRate() const {
        return counter_.measured() ? std::optional<double>(counter_.rate()) : std::nullopt;
    }

private:
    // iDate (and the wall clock it came from) of a frame at iTime t.time.
    void setDate(FrameTime& t, double wallClock) const;

    RealTimeClockOptions options_;
    double origin_;             // monotonic time that maps to startTime
    double pausedSince_ = 0;    // when paused: monotonic time of the pause
    bool paused_ = false;
    bool stepPending_ = false;
    bool forcePending_ = false;
    bool fresh_ = true;         // the next frame has no previous one to measure against
    long framesSinceRestart_ = 0;
    double lastTime_;
    SiteFrameRate counter_;
};

}  // namespace toyhost
