#include "timing/RealTimeClock.h"

#include "timing/FrameClock.h"

namespace toyhost {

namespace {
// Weight of the newest frame in the smoothed frame rate (about the last 10 frames count).
constexpr double kRateSmoothing = 0.1;
}  // namespace

RealTimeClock::RealTimeClock(const RealTimeClockOptions& options, double now)
    : options_(options), origin_(now), lastTime_(options.startTime), frameRate_(options.nominalFps) {
    if (options_.fixedFps) frameRate_ = *options_.fixedFps;
}

FrameTime RealTimeClock::frame(double now, double wallClock) {
    FrameTime t;
    if (options_.fixedFps) {
        const double fps = *options_.fixedFps;
        t.time = options_.startTime + static_cast<double>(framesSinceRestart_) / fps;
        t.timeDelta = 1.0 / fps;
        t.frameRate = fps;
        frameRate_ = fps;
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
        frameRate_ = fresh_ ? frameRate_ : frameRate_ + kRateSmoothing * (1.0 / t.timeDelta - frameRate_);
        t.frameRate = frameRate_;
    }
    t.date = dateAt(wallClock);
    lastTime_ = t.time;
    fresh_ = false;
    stepPending_ = false;
    ++framesSinceRestart_;
    return t;
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
}

void RealTimeClock::restart(double now) {
    origin_ = now;
    pausedSince_ = now;
    framesSinceRestart_ = 0;
    lastTime_ = options_.startTime;
    fresh_ = true;
}

}  // namespace toyhost
