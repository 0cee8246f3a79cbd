// xjorma's "Mountains & Lakes" (7tSSDD), verbatim from ../shared: the water simulation conserves
// its volume (the summed .y of Buffer C over the 256x256 grid stays 256*256*0.05), including
// through terrain transitions, and the Image shows lakes.
#include "GlTestSupport.h"

#include <cmath>

namespace toyhost::testing {
namespace {

class MountainsLakes : public GlTest {};

double totalWater(const std::vector<float>& rgba, int width) {
    double sum = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) sum += rgba[(static_cast<size_t>(y) * width + x) * 4 + 1];
    return sum;
}

TEST_F(MountainsLakes, WaterVolumeIsConservedFor300FramesAndImageShowsLakes) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD/image.glsl");
    constexpr int kW = 320, kH = 256, kFrames = 300;
    auto toy = loadSession(context_, sourceDir() / "shadertoys/mountains-lakes", kW, kH);
    ASSERT_TRUE(toy);
    const double expected = 256.0 * 256.0 * 0.05;
    std::vector<float> c;
    double worst = 0;
    int checks = 0;
    for (int n = 0; n < kFrames; ++n) {
        // Image only on the last frame: buffers alone drive the simulation.
        stepAt(*toy);
        if (n % 25 != 0 && n != kFrames - 1) continue;
        playerOf(*toy).readRgba32f(PassId::BufferC, c);
        const double total = totalWater(c, kW);
        const double relative = std::abs(total - expected) / expected;
        worst = std::max(worst, relative);
        ++checks;
        ASSERT_LT(relative, 1e-4) << "frame " << n << ": total water " << total << ", expected " << expected;
    }
    EXPECT_EQ(checks, 13);
    RecordProperty("worst_relative_error", std::to_string(worst));
    std::printf("worst relative water error over %d checks: %.3g\n", checks, worst);

    // The water must have moved: some cells are much deeper than the start level, some dry.
    double deepest = 0, driest = 1;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            const double depth = c[(static_cast<size_t>(y) * kW + x) * 4 + 1];
            deepest = std::max(deepest, depth);
            driest = std::min(driest, depth);
        }
    EXPECT_GT(deepest, 0.1) << "water never pooled into lakes";
    EXPECT_LT(driest, 0.01) << "no cell ever drained";

    std::vector<std::uint8_t> image;
    playerOf(*toy).readRgba8(PassId::Image, image);
    size_t blue = 0;
    double mean = 0, meanSq = 0;
    const size_t pixels = image.size() / 4;
    for (size_t i = 0; i < pixels; ++i) {
        const int r = image[4 * i], g = image[4 * i + 1], b = image[4 * i + 2];
        if (b > r + 40 && b > g + 20) ++blue;
        const double luma = 0.299 * r + 0.587 * g + 0.114 * b;
        mean += luma;
        meanSq += luma * luma;
    }
    mean /= pixels;
    const double stddev = std::sqrt(meanSq / pixels - mean * mean);
    EXPECT_GT(stddev, 20.0) << "the rendered frame is (nearly) uniform";
    EXPECT_GT(static_cast<double>(blue) / pixels, 0.05) << "no lakes: too few water-blue pixels";
    std::printf("image: luma stddev %.1f, water-blue pixels %.1f%%\n", stddev, 100.0 * blue / pixels);
}

}  // namespace
}  // namespace toyhost::testing
