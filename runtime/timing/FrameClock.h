// FrameClock: the fixed time step of headless runs (frame n has iTime = start + n / fps and
// iTimeDelta = 1 / fps) and the iDate that goes with it. Pure arithmetic; no GL needed.
// Also the wall-clock helpers behind iDate and --date.
#pragma once

#include <glm/vec4.hpp>
#include <optional>
#include <string>

#include "core/Result.h"
#include "timing/FrameTime.h"

namespace toyhost {

class FrameClock {
public:
    // `wallClockStart`: local wall-clock time at frame 0, in seconds since 1970-01-01 00:00
    // of the same wall clock (so the date fields come out without any time-zone work).
    FrameClock(double fps, double startTime, double wallClockStart);

    double fps() const { return fps_; }
    double time(int frame) const { return startTime_ + frame / fps_; }
    double timeDelta() const { return 1.0 / fps_; }
    // iDate = (year, month 0-11, day 1-31, seconds since midnight with fraction).
    glm::vec4 date(int frame) const;
    // Everything the Player needs for frame n: iTime, iTimeDelta, iFrameRate = fps, iDate.
    FrameTime frameTime(int frame) const {
        return {time(frame), timeDelta(), fps_, date(frame), wallClockStart_ + (time(frame) - startTime_)};
    }

private:
    double fps_;
    double startTime_;
    double wallClockStart_;
};

// The local wall clock now, in the form FrameClock expects.
double localWallClockNow();
// "YYYY-MM-DDTHH:MM:SS[.fff]" (or with a space) as the FrameClock wall-clock form.
Result<double> parseWallClock(const std::string& text);
// The other direction: "YYYY-MM-DDTHH:MM:SS.ffffff", which parseWallClock reads back to within a
// microsecond (for code that holds a wall clock and hands on a date setting).
std::string wallClockText(double wallClock);
// iDate for a moment of that wall clock.
glm::vec4 dateAt(double wallClock);
// iDate at iTime `time` of a run whose iTime `startTime` was at wall clock `wallClockStart`: the one
// rule for fixed steps (FrameClock, timing/Timeline.h) and for a window with --fps or --date.
glm::vec4 dateOfTime(double wallClockStart, double startTime, double time);

}  // namespace toyhost
