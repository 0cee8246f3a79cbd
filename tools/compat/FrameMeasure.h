// FrameMeasure: how much of an Image frame is not its dominant colour, the measure the
// compatibility probe calls a frame degenerate by, as pure functions (unit-tested without GL).
// No GL needed.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <unordered_map>

namespace toyhost::compat {

// A pixel within this many levels (of 255, in every one of R, G, B) of the dominant colour counts
// as that colour: dithering, banding noise and a 0.1/255 haze are not a picture.
inline constexpr int kColourTolerance = 2;

// A frame whose pixels differ from its dominant colour (beyond kColourTolerance) in less than
// this share is degenerate. Chosen from the share real shaders have (docs/compat-wild.md,
// "How degenerate is measured"): the lowest working frame of the public and wild corpora differs
// in 1.0% of its pixels (the median in 74%), a lone pixel in 0.007% and a faint haze in none.
inline constexpr double kMinOtherShare = 0.005;

struct FrameShare {
    std::array<std::uint8_t, 3> dominant{};  // the most frequent RGB value
    double dominantShare = 0;  // pixels within kColourTolerance of it, 0..1
    double otherShare = 0;     // the rest, 0..1
    double meanLevel = 0;      // mean of R, G and B over the frame, in levels of 255
};

inline bool nearColour(const std::uint8_t* pixel, const std::array<std::uint8_t, 3>& colour, int tolerance) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(static_cast<int>(pixel[k]) - static_cast<int>(colour[k])) > tolerance) return false;
    return true;
}

// `rgba` holds whole RGBA8 pixels; alpha is ignored (the site shows the Image opaque).
inline FrameShare measureFrame(std::span<const std::uint8_t> rgba, int tolerance = kColourTolerance) {
    FrameShare share;
    const std::size_t pixels = rgba.size() / 4;
    if (pixels == 0) return share;
    std::unordered_map<std::uint32_t, std::uint32_t> counts;
    std::uint32_t best = 0, bestCount = 0;
    double sum = 0;
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* p = &rgba[4 * i];
        const std::uint32_t key = (std::uint32_t{p[0]} << 16) | (std::uint32_t{p[1]} << 8) | p[2];
        const std::uint32_t n = ++counts[key];
        if (n > bestCount || (n == bestCount && key < best)) best = key, bestCount = n;
        sum += p[0] + p[1] + p[2];
    }
    share.dominant = {static_cast<std::uint8_t>(best >> 16), static_cast<std::uint8_t>(best >> 8),
                      static_cast<std::uint8_t>(best)};
    std::size_t near = 0;
    for (std::size_t i = 0; i < pixels; ++i) near += nearColour(&rgba[4 * i], share.dominant, tolerance);
    share.dominantShare = static_cast<double>(near) / static_cast<double>(pixels);
    share.otherShare = 1.0 - share.dominantShare;
    share.meanLevel = sum / (3.0 * static_cast<double>(pixels));
    return share;
}

// Nearly one colour: too few pixels differ from the dominant colour to be a picture.
inline bool nearlyUniform(const FrameShare& share, double minOtherShare = kMinOtherShare) {
    return share.otherShare < minOtherShare;
}

// Two dominant colours of frames judged at different times differ: a full-screen flash or fade.
inline bool colourChanged(const std::array<std::uint8_t, 3>& a, const std::array<std::uint8_t, 3>& b,
                          int tolerance = kColourTolerance) {
    return !nearColour(a.data(), b, tolerance);
}

}  // namespace toyhost::compat
