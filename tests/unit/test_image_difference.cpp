// compareImages (runtime/compare): PSNR, largest and mean difference, differing pixels, the first
// differing pixel and the difference image, on hand-made 8-bit images whose answers are worked
// out by hand. Pure, no GL.
#include <gtest/gtest.h>

#include <cmath>
#include <toyhost/Compare.h>

namespace toyhost {
namespace {

std::vector<std::uint8_t> filled(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
    // Sized first and written in place: inserting {r, g, b, a} at the end makes GCC 12 warn a false
    // -Wstringop-overflow.
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
        pixels[i] = r;
        pixels[i + 1] = g;
        pixels[i + 2] = b;
        pixels[i + 3] = a;
    }
    return pixels;
}

void set(std::vector<std::uint8_t>& pixels, int w, int x, int y, int channel, std::uint8_t value) {
    pixels[(static_cast<std::size_t>(y) * w + x) * 4 + channel] = value;
}

TEST(ImageDifference, IdenticalImagesHaveInfinitePsnrAndNoDifferingPixel) {
    const auto a = filled(4, 3, 10, 20, 30);
    Result<FrameDifference> d = compareImages(a, a, 4, 3, 3);
    ASSERT_TRUE(d.ok()) << d.error().text();
    EXPECT_TRUE(std::isinf(d->psnr) && d->psnr > 0);
    EXPECT_EQ(d->maxDiff, 0);
    EXPECT_EQ(d->meanDiff, 0.0);
    EXPECT_EQ(d->differingPixels, 0);
    EXPECT_EQ(d->firstX, -1);
    EXPECT_EQ(d->firstY, -1);
    EXPECT_TRUE(d->withinTolerance);
}

TEST(ImageDifference, OneSampleDifferenceGivesTheWorkedOutNumbers) {
    // 4x3 RGB = 36 samples; one differs by 12: MSE = 144 / 36 = 4, PSNR = 10 log10(65025 / 4).
    const auto a = filled(4, 3, 100, 100, 100);
    auto b = a;
    set(b, 4, 2, 1, 1, 112);
    Result<FrameDifference> d = compareImages(a, b, 4, 3, 3);
    ASSERT_TRUE(d.ok());
    EXPECT_NEAR(d->psnr, 10.0 * std::log10(65025.0 / 4.0), 1e-9);
    EXPECT_EQ(d->maxDiff, 12);
    EXPECT_NEAR(d->meanDiff, 12.0 / 36.0, 1e-12);
    EXPECT_EQ(d->differingPixels, 1);
    EXPECT_EQ(d->firstX, 2);
    EXPECT_EQ(d->firstY, 1);
    EXPECT_FALSE(d->withinTolerance) << "no tolerance: only identical frames are equal";
}

TEST(ImageDifference, FirstDifferingPixelIsTheFirstInRowOrder) {
    const auto a = filled(5, 4, 0, 0, 0);
    auto b = a;
    set(b, 5, 4, 3, 0, 1);  // last row
    set(b, 5, 3, 1, 2, 9);  // row 1, x 3: first in order
    set(b, 5, 0, 2, 0, 2);  // row 2
    Result<FrameDifference> d = compareImages(a, b, 5, 4, 3);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->firstX, 3);
    EXPECT_EQ(d->firstY, 1);
    EXPECT_EQ(d->differingPixels, 3);
    EXPECT_EQ(d->maxDiff, 9);
}

TEST(ImageDifference, AlphaCountsOnlyWithFourChannels) {
    const auto a = filled(2, 2, 50, 50, 50, 255);
    auto b = a;
    set(b, 2, 1, 1, 3, 0);  // alpha differs by 255
    Result<FrameDifference> rgb = compareImages(a, b, 2, 2, 3);
    ASSERT_TRUE(rgb.ok());
    EXPECT_TRUE(std::isinf(rgb->psnr)) << "Image's alpha is always 1: not compared";
    Result<FrameDifference> rgba = compareImages(a, b, 2, 2, 4);
    ASSERT_TRUE(rgba.ok());
    EXPECT_EQ(rgba->maxDiff, 255);
    // 16 samples, one off by 255: MSE = 65025 / 16, PSNR = 10 log10(16).
    EXPECT_NEAR(rgba->psnr, 10.0 * std::log10(16.0), 1e-9);
    EXPECT_EQ(rgba->firstX, 1);
    EXPECT_EQ(rgba->firstY, 1);
}

TEST(ImageDifference, TolerancesDecideEqualityAndWhichPixelsDiffer) {
    const auto a = filled(4, 4, 100, 100, 100);
    auto b = a;
    set(b, 4, 0, 0, 0, 101);  // off by 1
    set(b, 4, 2, 3, 2, 105);  // off by 5
    CompareTolerance maxDiff;
    maxDiff.maxDiff = 1;
    Result<FrameDifference> d = compareImages(a, b, 4, 4, 3, maxDiff);
    ASSERT_TRUE(d.ok());
    EXPECT_FALSE(d->withinTolerance);
    EXPECT_EQ(d->differingPixels, 1) << "the 1-level pixel is within --max-diff 1";
    EXPECT_EQ(d->firstX, 2);
    EXPECT_EQ(d->firstY, 3);
    maxDiff.maxDiff = 5;
    EXPECT_TRUE(compareImages(a, b, 4, 4, 3, maxDiff)->withinTolerance);

    // MSE = (1 + 25) / 48: PSNR = 10 log10(65025 * 48 / 26) = 50.79 dB.
    CompareTolerance psnr;
    psnr.minPsnr = 50.0;
    Result<FrameDifference> p = compareImages(a, b, 4, 4, 3, psnr);
    ASSERT_TRUE(p.ok());
    EXPECT_NEAR(p->psnr, 10.0 * std::log10(65025.0 * 48.0 / 26.0), 1e-9);
    EXPECT_TRUE(p->withinTolerance);
    EXPECT_EQ(p->differingPixels, 2);
    psnr.minPsnr = 51.0;
    EXPECT_FALSE(compareImages(a, b, 4, 4, 3, psnr)->withinTolerance);
    psnr.maxDiff = 4;
    psnr.minPsnr = 50.0;
    EXPECT_FALSE(compareImages(a, b, 4, 4, 3, psnr)->withinTolerance) << "both set: both must hold";
}

TEST(ImageDifference, DifferenceImageIsScaledAbsoluteDifferenceWithOpaqueAlpha) {
    const auto a = filled(3, 2, 100, 100, 100, 255);
    auto b = a;
    set(b, 3, 1, 0, 0, 103);  // +3: 24 at gain 8
    set(b, 3, 1, 0, 1, 90);   // -10: 80
    set(b, 3, 2, 1, 2, 200);  // +100: clamped to 255
    set(b, 3, 0, 1, 3, 7);    // alpha: not shown
    std::vector<std::uint8_t> diff;
    ASSERT_TRUE(compareImages(a, b, 3, 2, 4, {}, &diff).ok());
    ASSERT_EQ(diff.size(), 3u * 2 * 4);
    const std::vector<std::uint8_t> expected = {0, 0, 0, 255, 24, 80, 0, 255, 0, 0, 0, 255,
                                                0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 255, 255};
    EXPECT_EQ(diff, expected);
    ASSERT_TRUE(compareImages(a, b, 3, 2, 4, {}, &diff, 1).ok());
    EXPECT_EQ(diff[4], 3);
    EXPECT_EQ(diff[5], 10);
    EXPECT_EQ(diff[22], 100);
}

TEST(ImageDifference, WrongSizesAndChannelsAreErrors) {
    const auto a = filled(2, 2, 0, 0, 0);
    const auto small = filled(1, 2, 0, 0, 0);
    EXPECT_FALSE(compareImages(a, small, 2, 2, 3).ok());
    EXPECT_FALSE(compareImages(a, a, 3, 2, 3).ok());
    EXPECT_FALSE(compareImages(a, a, 2, 2, 2).ok());
    EXPECT_FALSE(compareImages(a, a, 2, 2, 5).ok());
    Result<FrameDifference> empty = compareImages({}, {}, 0, 0, 3);
    ASSERT_TRUE(empty.ok());
    EXPECT_TRUE(empty->withinTolerance);
}

}  // namespace
}  // namespace toyhost
