// SamplePattern: where and when a frame's Image pass is sampled when a capture asks for better
// pixels than the site's one sample per pixel at one instant: --supersample N draws it N x N
// times with fragCoord offset on a regular grid inside the pixel, --motion-blur S draws each offset
// at S times inside the shutter interval, and the draws are averaged (render/SampleAccumulator.h).
// With both, the shutter is cut into N x N x S equal strata and every draw gets one of its own
// (stratified time): each offset gets one stratum inside each of S equal parts, the offsets shuffled
// over the sub-strata of each part by a fixed permutation (deterministic). Pure logic; no GL needed.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Defaults.h"
#include "timing/FrameTime.h"

namespace toyhost {

// Where the shutter interval sits against the frame's time: opening at it (the default, the
// frame's instant and what follows), centred on it (Blender's and most film tools' convention), or
// closing at it.
enum class ShutterOffset { Open, Centre, Close };

struct SamplingDesc {
    int supersample = defaults::kSupersample;        // N: N x N offsets per pixel
    int motionBlur = defaults::kMotionBlurSamples;   // S: times per offset
    double shutterDegrees = defaults::kShutterDegrees;  // the interval: shutter / 360 of the frame step
    bool dither = false;  // an ordered dither before the average is rounded to 8 bits
    ShutterOffset shutterOffset = ShutterOffset::Open;
    bool linear = true;  // averaged in linear light (else the display values: render/SampleAccumulator.h)
};

// The words of --shutter-offset (open, centre or center, close) and --sample-space (linear,
// display); nullopt for any other.
std::optional<ShutterOffset> parseShutterOffset(std::string_view word);
std::optional<bool> parseSampleSpaceLinear(std::string_view word);

// One draw of the Image pass: fragCoord offset (pixels) and where in the frame step it is taken
// (0: the frame's time, 0.5: half a step later, negative: before it).
struct SamplePoint {
    glm::vec2 offset{0.0f};
    double fraction = 0;
};

// supersample^2 x motion blur: the draws of Image averaged into a frame.
inline int samplesPerFrame(const SamplingDesc& desc) { return desc.supersample * desc.supersample * desc.motionBlur; }

// True when a frame is one draw at the pixel centres at the frame's time: the site's pixels.
bool isSingleSample(const SamplingDesc& desc);

// The draws, part-major: for each part k of S, the offsets ((i + 0.5) / N - 0.5, (j + 0.5) / N -
// 0.5), j rows, i columns, offset o at the midpoint of stratum k * N^2 + perm_k(o) of N^2 S equal
// strata of the interval (all at fraction 0 when S = 1). The interval is shutter / 360 of the step
// and opens at 0, -half of it or -all of it (ShutterOffset). With N = 1 the times are the
// midpoints of S equal parts, as before stratification.
std::vector<SamplePoint> samplePattern(const SamplingDesc& desc);

// The clock of a sample taken `fraction` of the way through `frame`'s step: iTime moves, iDate
// follows it (by the wall clock when the frame's time has one, timing/FrameClock.h's rule), and
// iTimeDelta and iFrameRate stay the frame's.
FrameTime subFrameTime(const FrameTime& frame, double fraction);

}  // namespace toyhost
