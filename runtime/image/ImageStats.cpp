#include "image/ImageStats.h"

#include <cmath>
#include <limits>
#include <string>

namespace toyhost {

Result<std::array<ChannelStats, 4>> channelStats(const ImageF32& image, Region r) {
    if (r.width == 0 || r.height == 0) r = {0, 0, image.width, image.height};
    // In 64 bits: X + W of two large ints must not overflow (--region 2147483647,...).
    const auto end = [](int start, int size) { return static_cast<long long>(start) + size; };
    if (r.x < 0 || r.y < 0 || r.width < 0 || r.height < 0 || end(r.x, r.width) > image.width ||
        end(r.y, r.height) > image.height)
        return Error("region " + std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.width) +
                     "," + std::to_string(r.height) + " is outside the " + std::to_string(image.width) + "x" +
                     std::to_string(image.height) + " image", Code::InspectRegion);
    std::array<ChannelStats, 4> stats{};
    std::array<std::size_t, 4> finite{};
    for (auto& s : stats) {
        s.min = std::numeric_limits<double>::infinity();
        s.max = -std::numeric_limits<double>::infinity();
    }
    for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const double v = image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4 + c];
                ChannelStats& s = stats[c];
                if (std::isnan(v)) { ++s.nan; continue; }
                if (std::isinf(v)) { ++s.inf; continue; }
                s.sum += v;
                s.min = std::min(s.min, v);
                s.max = std::max(s.max, v);
                ++finite[c];
            }
    for (int c = 0; c < 4; ++c) {
        if (finite[c]) stats[c].mean = stats[c].sum / static_cast<double>(finite[c]);
        else stats[c].min = stats[c].max = 0;
    }
    return stats;
}

NonFiniteFind findNonFinite(std::span<const float> rgba, int width) {
    NonFiniteFind found;
    for (std::size_t i = 0; i < rgba.size(); ++i) {
        const float v = rgba[i];
        if (std::isfinite(v)) continue;
        if (found.count() == 0 && width > 0) {
            const std::size_t pixel = i / 4;
            found.x = static_cast<int>(pixel % static_cast<std::size_t>(width));
            found.y = static_cast<int>(pixel / static_cast<std::size_t>(width));
            found.channel = static_cast<int>(i % 4);
        }
        if (std::isnan(v)) ++found.nan;
        else ++found.inf;
    }
    return found;
}

}  // namespace toyhost
