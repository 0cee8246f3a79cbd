// Every uniform, the keyboard texture, vflip, wrap/filter samplers, stock media sizes, buffer
// mipmaps and the Image pass's iChN structs, read back raw from shadertoys/uniform-probe.
#include "GlTestSupport.h"

#include "input/InputEvent.h"

namespace toyhost::testing {
namespace {

class Uniforms : public GlTest {
protected:
    static constexpr int kW = 256, kH = 128;
    // llvmpipe turns 8-bit texels into floats to within about 1e-4, not exactly.
    static constexpr float k8BitTolerance = 0.25f / 255.0f;
    void SetUp() override {
        toy_ = loadSession(context_, sourceDir() / "shadertoys/uniform-probe", kW, kH, /*floatImage=*/true);
        ASSERT_TRUE(toy_);
    }
    // Renders the SessionCore's next frame and returns `pass`'s bottom row (pixel x at [4x .. 4x+3]).
    std::vector<float> render(PassId pass, std::span<const InputEvent> events = {}) {
        stepAt(*toy_, events);
        return read(pass);
    }
    std::vector<float> renderAt(const FrameTime& time, PassId pass) {
        EXPECT_TRUE(toy_->renderFrame(time, {}).ok());
        return read(pass);
    }
    std::vector<float> read(PassId pass) const {
        std::vector<float> rgba;
        playerOf(*toy_).readRgba32f(pass, rgba);
        return rgba;
    }
    static void expectPixel(const std::vector<float>& row, int x, float r, float g, float b, float a,
                            const char* what, float tolerance = 0.0f) {
        EXPECT_NEAR(row[4 * x + 0], r, tolerance) << what << " .x";
        EXPECT_NEAR(row[4 * x + 1], g, tolerance) << what << " .y";
        EXPECT_NEAR(row[4 * x + 2], b, tolerance) << what << " .z";
        EXPECT_NEAR(row[4 * x + 3], a, tolerance) << what << " .w";
    }
    std::unique_ptr<SessionCore> toy_;
};

TEST_F(Uniforms, ScalarAndVectorUniformsHaveShadertoyValues) {
    const FrameTime time{2.5, 1.0 / 30.0, 30.0, glm::vec4(2026.0f, 10.0f, 21.0f, 3600.5f)};
    auto a = renderAt(time, PassId::BufferA);
    expectPixel(a, 0, kW, kH, 1, 0, "iResolution");
    expectPixel(a, 1, 2.5f, 1.0f / 30.0f, 30.0f, 0.0f, "iTime, iTimeDelta, iFrameRate, iFrame");
    expectPixel(a, 3, 2026, 10, 21, 3600.5f, "iDate");
    expectPixel(a, 4, 256, 3, 1, 0, "iChannelResolution[0] (keyboard)");
    expectPixel(a, 5, 4, 2, 1, 0, "iChannelResolution[1] (4x2 image)");
    expectPixel(a, 6, kW, kH, 1, 0, "iChannelResolution[2] (buffer = canvas)");
    expectPixel(a, 7, 0, 0, 0, 0, "iChannelResolution[3] (nothing bound)");
    expectPixel(a, 8, 0, 0, 0, 0, "iChannelTime");
    EXPECT_EQ(a[4 * 9], 44100.0f) << "iSampleRate";
    // vflip = true: texel (0,0) is the file's bottom-left pixel (10, 20, 30, 40).
    expectPixel(a, 10, 10 / 255.f, 20 / 255.f, 30 / 255.f, 40 / 255.f, "vflip true", k8BitTolerance);
    while (playerOf(*toy_).frame() < 7) stepAt(*toy_);
    a = render(PassId::BufferA);
    EXPECT_EQ(a[4 * 1 + 3], 7.0f) << "iFrame";
}

TEST_F(Uniforms, MouseReachesTheShaderAsIMouse) {
    const InputEvent click[] = {InputEvent::mouseDown(30, 40)};
    expectPixel(render(PassId::BufferA, click), 2, 30, 40, 30, 40, "iMouse on the click frame");
    const InputEvent held[] = {InputEvent::mouseMove(35, 45)};
    expectPixel(render(PassId::BufferA, held), 2, 35, 45, 30, -40, "iMouse dragged, button down");
    const InputEvent release[] = {InputEvent::mouseMove(50, 60), InputEvent::mouseUp()};
    expectPixel(render(PassId::BufferA, release), 2, 50, 60, -30, -40, "iMouse after release");
}

TEST_F(Uniforms, KeyboardTextureRowsHeldWentDownToggle) {
    const InputEvent down[] = {InputEvent::keyDown(65)};
    const InputEvent up[] = {InputEvent::keyUp(65)};
    expectPixel(render(PassId::BufferA), 9, 44100, 0, 0, 0, "no key");
    expectPixel(render(PassId::BufferA, down), 9, 44100, 1, 1, 1, "A pressed this frame");
    expectPixel(render(PassId::BufferA), 9, 44100, 1, 0, 1, "A held");
    expectPixel(render(PassId::BufferA, up), 9, 44100, 0, 0, 1, "A released, toggle stays");
    expectPixel(render(PassId::BufferA, down), 9, 44100, 1, 1, 0, "A pressed again, toggle flips back");
}

TEST_F(Uniforms, SelfFeedbackCountsFrames) {
    std::vector<float> a;
    for (int n = 0; n < 5; ++n) a = render(PassId::BufferA);
    EXPECT_EQ(a[4 * 11], 5.0f);
}

TEST_F(Uniforms, SamplersFlipWrapFilterAndMipmapLikeShadertoy) {
    auto b = render(PassId::BufferB);
    expectPixel(b, 0, 1, 0, 0, 1, "vflip false: texel (0,0) is the file's top-left (red)", k8BitTolerance);
    expectPixel(b, 1, 10 / 255.f, 20 / 255.f, 30 / 255.f, 40 / 255.f, "repeat wrap", k8BitTolerance);
    expectPixel(b, 2, 30 / 255.f, 40 / 255.f, 50 / 255.f, 60 / 255.f, "linear filter", 1.5f / 255.f);
    expectPixel(b, 3, 64, 64, 1, 0, "stock RGBA Noise Small is 64x64");
    // Buffer C runs after B, so B sees C's previous frame: zero at frame 0, then its mean.
    expectPixel(b, 4, 0, 0, 0, 0, "mipmapped later buffer at frame 0");
    b = render(PassId::BufferB);
    // .y is a mediump 1/3: toyhost computes it in 32 bits as desktop GPUs do (fp16 would be 3e-4 off).
    expectPixel(b, 4, 0.5f, 1.0f / 3.0f, 0, 1, "top mip level of Buffer C is its mean", 1e-6f);
    // texelFetch (0,0) of the noise is the first row GL was given: the stand-in's bottom row
    // (vflip) or its top row.
    const ChannelDesc& noise = playerOf(*toy_).manifest().find(PassId::BufferB)->channels[2];
    const Image8* pixels = playerOf(*toy_).plan().images.find(noise);
    ASSERT_NE(pixels, nullptr);
    const std::size_t first = noise.sampler.vflip ? 0 : static_cast<std::size_t>(pixels->height - 1) * pixels->width * 4;
    expectPixel(b, 5, pixels->rgba[first] / 255.f, pixels->rgba[first + 1] / 255.f, pixels->rgba[first + 2] / 255.f,
                pixels->rgba[first + 3] / 255.f, "a texel of the stock noise", k8BitTolerance);
}

TEST_F(Uniforms, ImagePassHasChannelStructsAndAsserts) {
    auto image = render(PassId::Image);
    expectPixel(image, 0, kW, kH, 1, 1, "iCh0 (buffer) size and loaded");
    expectPixel(image, 1, 0, 0, 0, 1, "iCh1: nothing bound (alpha forced to 1)");
    expectPixel(image, 2, 256, 3, 1, 1, "iCh2 (keyboard)");
    const auto a = read(PassId::BufferA);
    expectPixel(image, 3, a[4], a[5], a[6], 1, "iCh0.sampler reads Buffer A");
    expectPixel(image, 4, 0, 1, 0, 1, "st_assert(false, 1) paints green");
    expectPixel(image, 5, 0, 0, 0, 1, "Image alpha is forced to 1");
}

}  // namespace
}  // namespace toyhost::testing
