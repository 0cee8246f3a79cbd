// Shadertoy's ping-pong rule and frame-0 clearing, proven value by value on float buffers with
// shadertoys/pingpong-probe (expected values are listed in its common.glsl).
#include "GlTestSupport.h"

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

class PingPong : public GlTest {};

void expectEveryPixel(const std::vector<float>& rgba, float r, float g, float b, float a, const char* what,
                      int frame) {
    for (size_t i = 0; i < rgba.size(); i += 4) {
        ASSERT_EQ(rgba[i + 0], r) << what << " .x, frame " << frame << ", pixel " << i / 4;
        ASSERT_EQ(rgba[i + 1], g) << what << " .y, frame " << frame << ", pixel " << i / 4;
        ASSERT_EQ(rgba[i + 2], b) << what << " .z, frame " << frame << ", pixel " << i / 4;
        ASSERT_EQ(rgba[i + 3], a) << what << " .w, frame " << frame << ", pixel " << i / 4;
    }
}

TEST_F(PingPong, BuffersFollowThisFramePreviousFrameRuleFromClearedStart) {
    auto toy = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8, /*floatImage=*/true);
    ASSERT_TRUE(toy);
    std::vector<float> a, b, image;
    for (int n = 0; n < 6; ++n) {
        stepAt(*toy);
        playerOf(*toy).readRgba32f(PassId::BufferA, a);
        playerOf(*toy).readRgba32f(PassId::BufferB, b);
        playerOf(*toy).readRgba32f(PassId::Image, image);
        const float f = static_cast<float>(n);
        // A reads itself and the later B: previous frame's values, zero at frame 0.
        expectEveryPixel(a, f + 1, f, 10 * f, 0.25f, "Buffer A", n);
        // B reads the earlier A: this frame's; itself: the previous frame's. Alpha is kept.
        expectEveryPixel(b, 10 * (f + 1), (f + 1) * (f + 2) / 2, f, 0.5f, "Buffer B", n);
        // Image sees this frame's A and B and has its alpha forced to 1.
        ASSERT_FLOAT_EQ(image[0], (f + 1) / 100.0f) << "frame " << n;
        ASSERT_FLOAT_EQ(image[1], 10 * (f + 1) / 1000.0f) << "frame " << n;
        ASSERT_FLOAT_EQ(image[2], (f + 1) * (f + 2) / 2 / 1000.0f) << "frame " << n;
        ASSERT_EQ(image[3], 1.0f) << "frame " << n;
    }
}

TEST_F(PingPong, CliExportsBufferAsRawFloatExr) {
    const auto dir = freshOutputDir("pingpong-exr");
    CommandResult run = runToyhost("run '" + (sourceDir() / "shadertoys/pingpong-probe").string() +
                                   "' --size 8x4 --frames 4 --capture-pass 'Buffer B' --out '" +
                                   (dir / "b_%02d.exr").string() + "' --quiet");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int n = 0; n < 4; ++n) {
        auto exr = readExr(dir / ("b_0" + std::to_string(n) + ".exr"));
        ASSERT_TRUE(exr.ok()) << exr.error().text();
        ASSERT_EQ(exr->width, 8);
        ASSERT_EQ(exr->height, 4);
        const float f = static_cast<float>(n);
        expectEveryPixel(exr->rgba, 10 * (f + 1), (f + 1) * (f + 2) / 2, f, 0.5f, "Buffer B (EXR)", n);
    }
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// Resize: new textures at the new size hold the old content in their bottom-left
// min(old, new) region (both slots), the rest is zero, and the frame count goes on.
TEST_F(PingPong, ResizeKeepsBufferContentBottomLeftInBothSlots) {
    auto toy = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8);
    ASSERT_TRUE(toy);
    for (int n = 0; n < 3; ++n) stepAt(*toy);
    ASSERT_TRUE(playerOf(*toy).resize(8, 12).ok());
    EXPECT_EQ(playerOf(*toy).width(), 8);
    std::vector<float> a;
    playerOf(*toy).readRgba32f(PassId::BufferA, a);
    ASSERT_EQ(a.size(), 8u * 12u * 4u);
    for (int y = 0; y < 12; ++y) {
        const float expected = y < 8 ? 3.0f : 0.0f;  // frame 2 wrote A.x = 3
        EXPECT_EQ(a[(y * 8 + 5) * 4], expected) << "row " << y;
    }
    // Frame 3 reads the other slot (frame 2's output survived there too): A.x = 4 where the old
    // content was copied, 1 in the new rows.
    stepAt(*toy);
    playerOf(*toy).readRgba32f(PassId::BufferA, a);
    EXPECT_EQ(a[(2 * 8 + 1) * 4], 4.0f);
    EXPECT_EQ(a[(10 * 8 + 1) * 4], 1.0f);
    EXPECT_EQ(a[(10 * 8 + 1) * 4 + 1], 3.0f) << "iFrame is not reset";
}

}  // namespace
}  // namespace toyhost::testing
