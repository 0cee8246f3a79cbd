// MipChain: the mip levels of an RGBA8 picture, built on the CPU with an exact 2x2 box filter
// (rounded to nearest, ties to even, as the browser's levels are). llvmpipe's glGenerateMipmap for RGBA8 comes out about half a level
// brighter per level (+3.8 at 1x1 on a mid-grey, reproduced outside toyhost); desktop drivers
// behind browsers average exactly, so toyhost uploads these levels instead. No GL needed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace toyhost {

struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Levels 1..n of a width x height RGBA8 picture (level 0 is the picture itself), down to 1x1.
// Level l is max(1, floor(w / 2^l)) x max(1, floor(h / 2^l)), as GL sizes them; each texel
// averages the 2x2 block under it (1x2 or 2x1 once a side is 1; an odd side's last row or
// column is left out, as a 2x2 box does).
std::vector<MipLevel> boxMipChain(std::span<const std::uint8_t> rgba, int width, int height);

struct VolumeMipLevel {
    int width = 0;
    int height = 0;
    int depth = 0;
    std::vector<std::uint8_t> voxels;  // `channels` bytes per voxel, x fastest, then y, then z
};

// Levels 1..n of a volume of `channels` (1..4) bytes per voxel, down to 1x1x1, with the same
// exact box filter in three dimensions (2x2x2, fewer along a side that is already 1).
std::vector<VolumeMipLevel> boxMipChain3D(std::span<const std::uint8_t> voxels, int width, int height, int depth,
                                          int channels);

}  // namespace toyhost
