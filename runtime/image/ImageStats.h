// Per-channel statistics of a float RGBA image region (sum, mean, min, max, NaN and Inf
// counts), used by `toyhost inspect` to check buffer dumps against invariants. No GL needed.
#pragma once

#include <array>
#include <cstddef>

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

}  // namespace toyhost
