#include "image/MipChain.h"

#include <algorithm>

namespace toyhost {

namespace {

// The average sum / count rounded to nearest, ties to even: what browsers' mipmaps give (webref
// probe mip_levels matches exactly; rounding ties up drifts +0.12 LSB per level, +1 at 1x1).
std::uint8_t roundHalfToEven(int sum, int count) {
    int q = sum / count;
    const int twice = 2 * (sum % count);
    if (twice > count || (twice == count && (q & 1))) ++q;
    return static_cast<std::uint8_t>(q);
}

}  // namespace

std::vector<MipLevel> boxMipChain(std::span<const std::uint8_t> rgba, int width, int height) {
    std::vector<MipLevel> levels;
    std::span<const std::uint8_t> source = rgba;
    int w = width, h = height;
    while (w > 1 || h > 1) {
        MipLevel level;
        level.width = std::max(1, w / 2);
        level.height = std::max(1, h / 2);
        level.rgba.resize(static_cast<std::size_t>(level.width) * level.height * 4);
        const int stepX = w > 1 ? 2 : 1, stepY = h > 1 ? 2 : 1;
        const int count = stepX * stepY;
        for (int y = 0; y < level.height; ++y)
            for (int x = 0; x < level.width; ++x)
                for (int c = 0; c < 4; ++c) {
                    int sum = 0;
                    for (int dy = 0; dy < stepY; ++dy)
                        for (int dx = 0; dx < stepX; ++dx)
                            sum += source[(static_cast<std::size_t>(y * stepY + dy) * w + (x * stepX + dx)) * 4 + c];
                    level.rgba[(static_cast<std::size_t>(y) * level.width + x) * 4 + c] =
                        roundHalfToEven(sum, count);
                }
        levels.push_back(std::move(level));
        source = levels.back().rgba;
        w = levels.back().width;
        h = levels.back().height;
    }
    return levels;
}

std::vector<VolumeMipLevel> boxMipChain3D(std::span<const std::uint8_t> voxels, int width, int height, int depth,
                                          int channels) {
    std::vector<VolumeMipLevel> levels;
    std::span<const std::uint8_t> source = voxels;
    int w = width, h = height, d = depth;
    while (w > 1 || h > 1 || d > 1) {
        VolumeMipLevel level;
        level.width = std::max(1, w / 2);
        level.height = std::max(1, h / 2);
        level.depth = std::max(1, d / 2);
        level.voxels.resize(static_cast<std::size_t>(level.width) * level.height * level.depth * channels);
        const int stepX = w > 1 ? 2 : 1, stepY = h > 1 ? 2 : 1, stepZ = d > 1 ? 2 : 1;
        const int count = stepX * stepY * stepZ;
        for (int z = 0; z < level.depth; ++z)
            for (int y = 0; y < level.height; ++y)
                for (int x = 0; x < level.width; ++x)
                    for (int c = 0; c < channels; ++c) {
                        int sum = 0;
                        for (int dz = 0; dz < stepZ; ++dz)
                            for (int dy = 0; dy < stepY; ++dy)
                                for (int dx = 0; dx < stepX; ++dx) {
                                    const std::size_t at = ((static_cast<std::size_t>(z * stepZ + dz) * h + (y * stepY + dy)) * w +
                                                            (x * stepX + dx)) * channels + c;
                                    sum += source[at];
                                }
                        const std::size_t to = ((static_cast<std::size_t>(z) * level.height + y) * level.width + x) * channels + c;
                        level.voxels[to] = static_cast<std::uint8_t>((sum + count / 2) / count);
                    }
        levels.push_back(std::move(level));
        source = levels.back().voxels;
        w = levels.back().width;
        h = levels.back().height;
        d = levels.back().depth;
    }
    return levels;
}

}  // namespace toyhost
