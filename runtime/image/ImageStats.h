// Per-channel statistics of a float RGBA image region (sum, mean, min, max, NaN and Inf
// counts), used by `toyhost inspect` to check buffer dumps against invariants. No GL needed.
#pragma once

#include <array>
#include <cstddef>
#include <span>

#include "core/Result.h"
#include "image/Image.h"

namespace toyhost {

struct Region {
    int x = 0, y = 0, width = 0, height = 0;  // origin bottom-left, like gl_FragCoord
};

struct ChannelStats {
    double sum = 0, min = 0, max = 0, mean = 0;
    std::size_t nan = 0, inf = 0;
};

// Statistics over `region` (the whole image when its width or height is 0). Non-finite values
// are counted, not summed.
Result<std::array<ChannelStats, 4>> channelStats(const ImageF32& image, Region region);

// NaN and Inf values of an RGBA float image: how many, and the first one (rows bottom first, as
// gl_FragCoord counts them). count == 0 when every value is finite.
struct NonFiniteFind {
    std::size_t nan = 0;
    std::size_t inf = 0;
    int x = 0, y = 0, channel = 0;  // the first non-finite value
    std::size_t count() const { return nan + inf; }
};

// Scans `rgba` (width * height * 4 floats, rows bottom first). Allocates nothing.
NonFiniteFind findNonFinite(std::span<const float> rgba, int width);

}  // namespace toyhost
