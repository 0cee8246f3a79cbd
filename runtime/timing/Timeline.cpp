#include "timing/Timeline.h"

#include <utility>

namespace toyhost {

Timeline::Timeline(TimelineDesc desc)
    : desc_(std::move(desc)), clock_(desc_.fps, desc_.startTime, desc_.wallClockStart), mouse_(desc_.mouse),
      keys_(desc_.keys) {}

FrameTime Timeline::at(int frame, double fraction) const {
    // (frame + 0.0) / fps is frame / fps exactly: a whole frame's time is FrameClock's.
    return atTime(desc_.startTime + (frame + fraction) / clock_.fps(), clock_.timeDelta(), clock_.fps());
}

FrameTime Timeline::atTime(double time, double timeDelta, double frameRate) const {
    return {time, timeDelta, frameRate, dateOfTime(desc_.wallClockStart, desc_.startTime, time),
            desc_.wallClockStart + (time - desc_.startTime)};
}

void Timeline::eventsBefore(int frame, std::vector<InputEvent>& out) {
    for (; nextFrame_ < frame; ++nextFrame_) {
        skipped_.clear();
        const double time = clock_.time(nextFrame_);
        mouse_.eventsBeforeFrame(nextFrame_, time, skipped_);
        keys_.eventsBeforeFrame(nextFrame_, time, skipped_);
    }
    if (frame < nextFrame_) return;  // already taken (the same frame asked twice)
    const double time = clock_.time(frame);
    mouse_.eventsBeforeFrame(frame, time, out);
    keys_.eventsBeforeFrame(frame, time, out);
    nextFrame_ = frame + 1;
}

void Timeline::restart() {
    mouse_ = MouseScriptPlayer(desc_.mouse);
    keys_ = KeyScriptPlayer(desc_.keys);
    nextFrame_ = 0;
}

}  // namespace toyhost
