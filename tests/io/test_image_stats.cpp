#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/ImageStats.h"

namespace toyhost {
namespace {

ImageF32 gradient(int w, int h) {
    ImageF32 image{w, h, std::vector<float>(static_cast<size_t>(w) * h * 4)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &image.rgba[(static_cast<size_t>(y) * w + x) * 4];
            p[0] = float(x);
            p[1] = float(y);
            p[2] = 1.0f;
            p[3] = -1.0f;
        }
    return image;
}

TEST(ImageStats, SumsMeansAndExtremesPerChannel) {
    auto stats = channelStats(gradient(4, 3), {});
    ASSERT_TRUE(stats.ok());
    EXPECT_EQ((*stats)[0].sum, 3 * (0 + 1 + 2 + 3));
    EXPECT_EQ((*stats)[1].sum, 4 * (0 + 1 + 2));
    EXPECT_EQ((*stats)[0].max, 3);
    EXPECT_EQ((*stats)[1].min, 0);
    EXPECT_EQ((*stats)[2].mean, 1);
    EXPECT_EQ((*stats)[3].mean, -1);
}

TEST(ImageStats, RegionIsBottomLeftOriginAndChecked) {
    auto stats = channelStats(gradient(4, 3), {1, 1, 2, 2});
    ASSERT_TRUE(stats.ok());
    EXPECT_EQ((*stats)[0].sum, 2 * (1 + 2));
    EXPECT_EQ((*stats)[1].sum, 2 * (1 + 2));
    auto outside = channelStats(gradient(4, 3), {2, 0, 3, 1});
    ASSERT_FALSE(outside.ok());
    EXPECT_NE(outside.error().text().find("outside the 4x3 image"), std::string::npos);
}

TEST(ImageStats, NonFiniteValuesAreCountedNotSummed) {
    ImageF32 image = gradient(2, 1);
    image.rgba[0] = std::numeric_limits<float>::quiet_NaN();
    image.rgba[4] = std::numeric_limits<float>::infinity();
    auto stats = channelStats(image, {});
    ASSERT_TRUE(stats.ok());
    EXPECT_EQ((*stats)[0].nan, 1u);
    EXPECT_EQ((*stats)[0].inf, 1u);
    EXPECT_EQ((*stats)[0].sum, 0);
    EXPECT_EQ((*stats)[1].nan, 0u);
}

}  // namespace
}  // namespace toyhost
