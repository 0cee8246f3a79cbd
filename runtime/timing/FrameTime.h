// FrameTime: the clock side of a frame's uniforms, which a driver's clock (timing/FrameClock.h
// for fixed steps, timing/RealTimeClock.h for a window) fills and the Player renders with.
// Plain data; no GL needed.
#pragma once

#include <optional>

#include <glm/vec4.hpp>

namespace toyhost {

struct FrameTime {
    double time = 0;       // iTime
    double timeDelta = 0;  // iTimeDelta
    double frameRate = 0;  // iFrameRate
    glm::vec4 date{0};     // iDate (year, month 0-11, day, seconds since midnight)
    // The wall clock (timing/FrameClock.h's form) iDate was made from, when the clock knows it:
    // a sample inside the frame (timing/SamplePattern.h) gets its iDate by the same rule.
    std::optional<double> wallClock;
};

}  // namespace toyhost
