#include "timing/RealTimeClock.h"

#include "timing/FrameClock.h"

namespace toyhost {

RealTimeClock::RealTimeClock(const RealTimeClockOptions& options, double now)
    : options_(options), origin_(now), lastTime_(options.startTime), counter_(now) {}

FrameTime RealTimeClock::frame(double now, double wallClock) {
    FrameTime t;
    // The site counts every frame it paints, forced ones included, before painting it.
    counter_.count(now);
    if (forcePending_ && !stepPending_ && paused_) {
        // Forced while paused: the paused time again (the site paints mTf with a 1/60 delta).
        t.time = lastTime_;
        t.timeDelta = 1.0 / options_.nominalFps;
        t.frameRate = options_.fixedFps ? *options_.fixedFps : counter_.rate();
    } else if (options_.fixedFps) {
        const double fps = *options_.fixedFps;
        t.time = options_.startTime + static_cast<double>(framesSinceRestart_) / fps;
        t.timeDelta = 1.0 / fps;
        t.frameRate = fps;
        ++framesSinceRestart_;
    } else {
        if (stepPending_) {
            // A single step while paused: one nominal frame later, and the clock stays put.
            t.time = lastTime_ + 1.0 / options_.nominalFps;
            origin_ -= 1.0 / options_.nominalFps;
        } else {
            t.time = options_.startTime + (now - origin_);
        }
        t.timeDelta = fresh_ || stepPending_ ? 1.0 / options_.nominalFps : t.time - lastTime_;
        if (t.timeDelta <= 0) t.timeDelta = 1.0 / options_.nominalFps;
        t.frameRate = counter_.rate();
        ++framesSinceRestart_;
    }
    setDate(t, wallClock);
    lastTime_ = t.time;
    fresh_ = false;
    stepPending_ = false;
    forcePending_ = false;
    return t;
}

FrameTime RealTimeClock::repaint(double now, double wallClock) {
    counter_.count(now);
    FrameTime t;
    t.time = lastTime_;
    t.timeDelta = 1.0 / options_.nominalFps;
    t.frameRate = options_.fixedFps ? *options_.fixedFps : counter_.rate();
    setDate(t, wallClock);
    return t;
}

void RealTimeClock::setDate(FrameTime& t, double wallClock) const {
    t.wallClock = options_.wallClockStart ? *options_.wallClockStart + (t.time - options_.startTime) : wallClock;
    t.date = options_.wallClockStart ? dateOfTime(*options_.wallClockStart, options_.startTime, t.time)
                                     : dateAt(wallClock);
}

void RealTimeClock::setPaused(bool paused, double now) {
    if (paused == paused_) return;
    if (paused) {
        pausedSince_ = now;
    } else {
        origin_ += now - pausedSince_;  // the paused span does not count
        fresh_ = true;
    }
    paused_ = paused;
    stepPending_ = false;
    forcePending_ = false;
}

void RealTimeClock::restart(double now) {
    origin_ = now;
    pausedSince_ = now;
    framesSinceRestart_ = 0;
    lastTime_ = options_.startTime;
    fresh_ = true;
    forcePending_ = paused_;  // the site paints the restarted frame even while paused
}

}  // namespace toyhost
