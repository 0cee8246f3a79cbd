// SamplePattern: where and when a frame's Image pass is sampled when a capture asks for better
// pixels than the site's one sample per pixel at one instant: --supersample N draws it N x N
// times with fragCoord offset on a regular grid inside the pixel, --motion-blur S draws it at S
// times inside the shutter interval that opens at the frame's time, and the draws are averaged.
// Every pair of a spatial offset and a time is drawn (N x N x S draws), so each pixel gets the
// same N x N offsets at each of the S times. Pure logic; no GL needed.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

#include "core/Defaults.h"
#include "timing/FrameTime.h"

namespace toyhost {

struct SamplingDesc {
    int supersample = defaults::kSupersample;        // N: N x N offsets per pixel
    int motionBlur = defaults::kMotionBlurSamples;   // S: times per frame
    double shutterDegrees = defaults::kShutterDegrees;  // the interval: shutter / 360 of the frame step
    bool dither = false;  // an ordered dither before the average is rounded to 8 bits
};

// One draw of the Image pass: fragCoord offset (pixels) and where in the frame step it is taken
// (0: the frame's time, 0.5: half a step later).
struct SamplePoint {
    glm::vec2 offset{0.0f};
    double fraction = 0;
};

// supersample^2 x motion blur: the draws of Image averaged into a frame.
inline int samplesPerFrame(const SamplingDesc& desc) { return desc.supersample * desc.supersample * desc.motionBlur; }

// True when a frame is one draw at the pixel centres at the frame's time: the site's pixels.
bool isSingleSample(const SamplingDesc& desc);

// The draws, time-major: for each time k (fractions (k + 0.5) / S * shutter / 360, or 0 when
// S = 1), the offsets ((i + 0.5) / N - 0.5, (j + 0.5) / N - 0.5), j rows, i columns.
std::vector<SamplePoint> samplePattern(const SamplingDesc& desc);

// The clock of a sample taken `fraction` of the way through `frame`'s step: iTime moves, iDate
// follows it (by the wall clock when the frame's time has one, timing/FrameClock.h's rule), and
// iTimeDelta and iFrameRate stay the frame's.
FrameTime subFrameTime(const FrameTime& frame, double fraction);

}  // namespace toyhost
