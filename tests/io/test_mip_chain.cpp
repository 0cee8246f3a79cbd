// MipChain: the CPU box filter that replaces llvmpipe's glGenerateMipmap for RGBA8 pictures:
// level sizes as GL's, exact averages rounded to nearest with ties to even (the browser's), down to 1x1.
#include <gtest/gtest.h>

#include <vector>

#include "image/MipChain.h"

using namespace toyhost;

TEST(MipChain, LevelSizesFollowGlDownToOneByOne) {
    const std::vector<std::uint8_t> pixels(static_cast<std::size_t>(5) * 3 * 4, 7);
    const std::vector<MipLevel> levels = boxMipChain(pixels, 5, 3);
    ASSERT_EQ(levels.size(), 2u);  // 5x3 -> 2x1 -> 1x1
    EXPECT_EQ(levels[0].width, 2);
    EXPECT_EQ(levels[0].height, 1);
    EXPECT_EQ(levels[1].width, 1);
    EXPECT_EQ(levels[1].height, 1);
    for (const MipLevel& l : levels)
        for (std::uint8_t v : l.rgba) EXPECT_EQ(v, 7);
    EXPECT_TRUE(boxMipChain(std::vector<std::uint8_t>(4, 1), 1, 1).empty());
}

TEST(MipChain, AMidGreyStaysExactAtEveryLevel) {
    // llvmpipe drifts +0.5 LSB per level here (128 -> 131.8 at 1x1); a box filter keeps 128.
    const int side = 256;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(side) * side * 4);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = (i / 4) % 2 ? 127 : 129;
    const std::vector<MipLevel> levels = boxMipChain(pixels, side, side);
    ASSERT_EQ(levels.size(), 8u);
    for (const MipLevel& l : levels) EXPECT_EQ(l.rgba[0], 128) << l.width;
}

TEST(MipChain, EachTexelIsTheRoundedAverageOfTheBlockBelowIt) {
    // 2x2 RGBA: channel values chosen so the sums end in .25, .5 and .75.
    const std::vector<std::uint8_t> pixels{0, 1, 2, 255, 0, 0, 0, 255, 1, 1, 1, 255, 0, 0, 2, 254};
    const std::vector<MipLevel> levels = boxMipChain(pixels, 2, 2);
    ASSERT_EQ(levels.size(), 1u);
    // R: 1/4 = 0.25 -> 0; G: 2/4 = 0.5 -> 0 (tie to even); B: 5/4 = 1.25 -> 1; A: 1019/4 = 254.75 -> 255.
    EXPECT_EQ(levels[0].rgba, (std::vector<std::uint8_t>{0, 0, 1, 255}));
    // A 1-pixel-high row averages pairs.
    const std::vector<std::uint8_t> row{10, 10, 10, 10, 20, 20, 20, 20};
    EXPECT_EQ(boxMipChain(row, 2, 1)[0].rgba, (std::vector<std::uint8_t>{15, 15, 15, 15}));
}

TEST(MipChain, TiesRoundToEvenAsTheBrowsersLevelsDo) {
    // Issue 30 (webref probe mip_levels): rounding ties up drifts +0.12 LSB per level; the
    // browser's levels are the exact average with ties to even.
    // Sums per channel 2, 6, 10, 1018 over 4: 0.5 -> 0, 1.5 -> 2, 2.5 -> 2, 254.5 -> 254.
    const std::vector<std::uint8_t> pixels{2, 6, 10, 255, 0, 0, 0, 255, 0, 0, 0, 254, 0, 0, 0, 254};
    EXPECT_EQ(boxMipChain(pixels, 2, 2)[0].rgba, (std::vector<std::uint8_t>{0, 2, 2, 254}));
    // Pairs (a side already 1): 21 / 2 = 10.5 -> 10, 23 / 2 = 11.5 -> 12.
    const std::vector<std::uint8_t> row{10, 11, 0, 0, 11, 12, 0, 0};
    EXPECT_EQ(boxMipChain(row, 2, 1)[0].rgba, (std::vector<std::uint8_t>{10, 12, 0, 0}));
}

// Volumes: each level averages the 2x2x2 block under each voxel (rounded to nearest), per channel,
// down to 1x1x1; a side already 1 is not halved again.
TEST(MipChain, VolumeLevelsAverageTwoByTwoByTwoBlocks) {
    // 4x2x2, 2 channels: channel 0 is the voxel's index, channel 1 is 200 - 10 * z.
    std::vector<std::uint8_t> voxels;
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x) {
                voxels.push_back(static_cast<std::uint8_t>((z * 2 + y) * 4 + x));
                voxels.push_back(static_cast<std::uint8_t>(200 - 10 * z));
            }
    const std::vector<VolumeMipLevel> levels = boxMipChain3D(voxels, 4, 2, 2, 2);
    ASSERT_EQ(levels.size(), 2u);
    ASSERT_EQ(levels[0].width, 2);
    ASSERT_EQ(levels[0].height, 1);
    ASSERT_EQ(levels[0].depth, 1);
    // Block x 0-1: indices 0,1,4,5,8,9,12,13 -> 52/8 = 6.5 -> 7; x 2-3: 68/8 = 8.5 -> 9.
    EXPECT_EQ(levels[0].voxels, (std::vector<std::uint8_t>{7, 195, 9, 195}));
    ASSERT_EQ(levels[1].width, 1);
    EXPECT_EQ(levels[1].voxels, (std::vector<std::uint8_t>{8, 195}));
    EXPECT_TRUE(boxMipChain3D(std::vector<std::uint8_t>(1, 9), 1, 1, 1, 1).empty());
}
