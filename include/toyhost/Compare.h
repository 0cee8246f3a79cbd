// toyhost/Compare.h (public API, stable): two shadertoys rendered with the same inputs (size, fps,
// start time, date, mouse and key scripts) and compared frame by frame: PSNR, largest and mean
// difference, differing pixels, the first differing frame and pixel, and difference images. For
// ports ("does my port still match the original?") and for scoring generated shader code.
// compareShadertoys needs no GL context of the caller's (it renders headless, like
// Session::createHeadless: call it on a thread with a large stack, see runOnGlThread); the
// tolerance, the measures of a frame and compareImages, plain arithmetic, are toyhost/CompareTypes.h.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <toyhost/CompareTypes.h>
#include <toyhost/Export.h>
#include <toyhost/Input.h>
#include <toyhost/Result.h>
#include <toyhost/Settings.h>
#include <toyhost/Shadertoy.h>

namespace toyhost {

// One compared frame as it is rendered, for callers that write files or stop early: the two
// frames and the difference image (empty when within tolerance), rows top first.
struct ComparedFrame {
    const FrameDifference& difference;
    int width;   // each image: width * height * 4 bytes, RGBA8
    int height;
    std::span<const std::uint8_t> a;
    std::span<const std::uint8_t> b;
    std::span<const std::uint8_t> diffImage;
};

struct CompareSettings {
    // Size, fps, start time, date, media, input scripts and limits, the same for both (absent means
    // the default, as for a Session; an absent date is fixed to now once, so both see the same
    // iDate). The scripts are replayed for both.
    SessionSettings session;
    int frames = 0;                // frames rendered and compared; 0: toyhost's default run length
    std::string pass = "Image";    // "Image" or "Buffer A" .. "Buffer D"
    CompareTolerance tolerance;
    // More events for both, before frame `frame` (at iTime `time`), after the scripts' events.
    std::function<std::vector<InputEvent>(int frame, double time)> input;
    bool keepDiffImages = false;   // FrameDifference::diffImage for frames beyond the tolerance
    bool diffImages = false;       // make difference images for `onFrame` (implied by keepDiffImages)
    int diffGain = 0;              // difference image scale; 0: toyhost's default (8)
    // Called after each frame is compared (on the calling thread); return false to stop early.
    std::function<bool(const ComparedFrame&)> onFrame;
};

struct CompareReport {
    int width = 0;       // the canvas both rendered at
    int height = 0;
    double fps = 0;      // the time step both used: frame n at iTime = startTime + n / fps
    double startTime = 0;
    std::string pass;
    std::vector<FrameDifference> frames;     // every frame compared, in order
    std::optional<int> firstDifferingFrame;  // the first frame beyond the tolerance (its iFrame)
    double minPsnr = 0;                      // the worst frame's PSNR (+infinity when all identical)
    int maxDiff = 0;                         // the largest difference of any frame
    bool equal() const { return !firstDifferingFrame; }
};

// Renders `a` and `b` headless, frame by frame with the same settings and inputs, and compares
// `settings.pass`. Errors: either shadertoy failing to start (named "A: ..." / "B: ..." through
// the diagnostics' file), a pass that one of them lacks, scripts that do not parse, a GL error.
TOYHOST_API Result<CompareReport> compareShadertoys(const Shadertoy& a, const Shadertoy& b,
                                                   const CompareSettings& settings = {});

}  // namespace toyhost
