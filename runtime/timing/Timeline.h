// Timeline: the one fixed-step input of every headless loop (the headless driver, the library's
// Session, `toyhost compare`, the compatibility probe): frame n's clock (iTime = start + n / fps,
// iTimeDelta = 1 / fps, iFrameRate = fps, and the iDate that follows iTime) and the scripted mouse
// and key events due before it. Sub-frame times (frame n at a fraction of its step) are the same
// arithmetic, for samples taken inside a frame. The window's real-time clock shares its iDate rule
// (dateOfTime, timing/FrameClock.h). Pure logic; no GL needed.
#pragma once

#include <vector>

#include "core/Defaults.h"
#include "input/InputEvent.h"
#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "timing/FrameClock.h"
#include "timing/FrameTime.h"

namespace toyhost {

struct TimelineDesc {
    double fps = defaults::kFps;
    double startTime = 0;
    // The wall clock (localWallClockNow's form) at iTime = startTime: iDate follows iTime from it.
    double wallClockStart = 0;
    MouseScript mouse;
    KeyScript keys;
};

class Timeline {
public:
    explicit Timeline(TimelineDesc desc);

    double fps() const { return clock_.fps(); }
    double startTime() const { return desc_.startTime; }
    double wallClockStart() const { return desc_.wallClockStart; }

    // Frame n's clock; `fraction` in [0, 1) moves iTime (and iDate) inside the frame's step while
    // iTimeDelta and iFrameRate stay the frame's.
    FrameTime at(int frame, double fraction = 0) const;
    // The clock of a frame at any iTime (a caller that sets its own times): iDate follows iTime by
    // the same rule, iTimeDelta and iFrameRate as given.
    FrameTime atTime(double time, double timeDelta, double frameRate) const;

    // Appends the scripted events due before frame n (at its iTime), in script order. Frames go
    // forward; a jump (a run resumed from a checkpoint, a frame range) replays the skipped frames'
    // events and drops them: their effect is in the state the run continues from. restart() goes
    // back to frame 0.
    void eventsBefore(int frame, std::vector<InputEvent>& out);
    // Both: frame n's clock, with its events appended to `events`.
    FrameTime next(int frame, std::vector<InputEvent>& events) {
        eventsBefore(frame, events);
        return at(frame);
    }
    void restart();

private:
    TimelineDesc desc_;
    FrameClock clock_;
    MouseScriptPlayer mouse_;
    KeyScriptPlayer keys_;
    int nextFrame_ = 0;  // the scripts' next frame
    std::vector<InputEvent> skipped_;
};

}  // namespace toyhost
