// Every uniform, the keyboard texture, vflip, wrap/filter samplers, stock media sizes, buffer
// mipmaps and the Image pass's iChN structs, read back raw from shadertoys/uniform-probe.
#include "GlTestSupport.h"

#include "input/KeyboardState.h"
#include "input/MouseState.h"

namespace toyhost::testing {
namespace {

class Uniforms : public GlTest {
protected:
    static constexpr int kW = 256, kH = 128;
    // llvmpipe turns 8-bit texels into floats to within about 1e-4, not exactly.
    static constexpr float k8BitTolerance = 0.25f / 255.0f;
    void SetUp() override {
        toy_ = loadShadertoy(sourceDir() / "shadertoys/uniform-probe", kW, kH, /*floatImage=*/true);
        ASSERT_TRUE(toy_);
    }
    // Renders a frame and returns `pass`'s bottom row (pixel x at [4x .. 4x+3]).
    std::vector<float> render(const FrameUniforms& u, PassId pass) {
        toy_->renderer->renderFrame(u);
        std::vector<float> rgba;
        toy_->renderer->readRgba32f(pass, rgba);
        return rgba;
    }
    static void expectPixel(const std::vector<float>& row, int x, float r, float g, float b, float a,
                            const char* what, float tolerance = 0.0f) {
        EXPECT_NEAR(row[4 * x + 0], r, tolerance) << what << " .x";
        EXPECT_NEAR(row[4 * x + 1], g, tolerance) << what << " .y";
        EXPECT_NEAR(row[4 * x + 2], b, tolerance) << what << " .z";
        EXPECT_NEAR(row[4 * x + 3], a, tolerance) << what << " .w";
    }
    std::unique_ptr<LoadedShadertoy> toy_;
};

TEST_F(Uniforms, ScalarAndVectorUniformsHaveShadertoyValues) {
    FrameUniforms u = toy_->uniforms(0, 30.0f);
    u.time = 2.5f;
    u.date = {2026.0f, 10.0f, 21.0f, 3600.5f};
    auto a = render(u, PassId::BufferA);
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
    u.frame = 7;
    a = render(u, PassId::BufferA);
    EXPECT_EQ(a[4 * 1 + 3], 7.0f) << "iFrame";
}

TEST_F(Uniforms, MouseReachesTheShaderAsIMouse) {
    MouseState mouse;
    mouse.press(30, 40);
    FrameUniforms u = toy_->uniforms(0);
    u.mouse = mouse.uniform();
    expectPixel(render(u, PassId::BufferA), 2, 30, 40, 30, 40, "iMouse on the click frame");
    mouse.endFrame();
    mouse.move(50, 60);
    mouse.release();
    u = toy_->uniforms(1);
    u.mouse = mouse.uniform();
    expectPixel(render(u, PassId::BufferA), 2, 50, 60, -30, -40, "iMouse after release");
}

TEST_F(Uniforms, KeyboardTextureRowsHeldWentDownToggle) {
    KeyboardState keys;
    auto frame = [&](int n) {
        toy_->renderer->updateKeyboard(keys.texels());
        auto a = render(toy_->uniforms(n), PassId::BufferA);
        keys.endFrame();
        return a;
    };
    expectPixel(frame(0), 9, 44100, 0, 0, 0, "no key");
    keys.press(65);
    expectPixel(frame(1), 9, 44100, 1, 1, 1, "A pressed this frame");
    expectPixel(frame(2), 9, 44100, 1, 0, 1, "A held");
    keys.release(65);
    expectPixel(frame(3), 9, 44100, 0, 0, 1, "A released, toggle stays");
    keys.press(65);
    expectPixel(frame(4), 9, 44100, 1, 1, 0, "A pressed again, toggle flips back");
}

TEST_F(Uniforms, SelfFeedbackCountsFrames) {
    std::vector<float> a;
    for (int n = 0; n < 5; ++n) a = render(toy_->uniforms(n), PassId::BufferA);
    EXPECT_EQ(a[4 * 11], 5.0f);
}

TEST_F(Uniforms, SamplersFlipWrapFilterAndMipmapLikeShadertoy) {
    auto b = render(toy_->uniforms(0), PassId::BufferB);
    expectPixel(b, 0, 1, 0, 0, 1, "vflip false: texel (0,0) is the file's top-left (red)", k8BitTolerance);
    expectPixel(b, 1, 10 / 255.f, 20 / 255.f, 30 / 255.f, 40 / 255.f, "repeat wrap", k8BitTolerance);
    expectPixel(b, 2, 30 / 255.f, 40 / 255.f, 50 / 255.f, 60 / 255.f, "linear filter", 1.5f / 255.f);
    expectPixel(b, 3, 64, 64, 1, 0, "stock RGBA Noise Small is 64x64");
    // Buffer C runs after B, so B sees C's previous frame: zero at frame 0, then its mean.
    expectPixel(b, 4, 0, 0, 0, 0, "mipmapped later buffer at frame 0");
    b = render(toy_->uniforms(1), PassId::BufferB);
    // .y is a mediump 1/3: toyhost computes it in 32 bits as desktop GPUs do (fp16 would be 3e-4 off).
    expectPixel(b, 4, 0.5f, 1.0f / 3.0f, 0, 1, "top mip level of Buffer C is its mean", 1e-6f);
    for (int k = 0; k < 4; ++k) {
        EXPECT_GE(b[4 * 5 + k], 0.0f);
        EXPECT_LE(b[4 * 5 + k], 1.0f);
    }
}

TEST_F(Uniforms, ImagePassHasChannelStructsAndAsserts) {
    auto image = render(toy_->uniforms(0), PassId::Image);
    expectPixel(image, 0, kW, kH, 1, 1, "iCh0 (buffer) size and loaded");
    expectPixel(image, 1, 0, 0, 0, 1, "iCh1: nothing bound (alpha forced to 1)");
    expectPixel(image, 2, 256, 3, 1, 1, "iCh2 (keyboard)");
    auto a = std::vector<float>();
    toy_->renderer->readRgba32f(PassId::BufferA, a);
    expectPixel(image, 3, a[4], a[5], a[6], 1, "iCh0.sampler reads Buffer A");
    expectPixel(image, 4, 0, 1, 0, 1, "st_assert(false, 1) paints green");
    expectPixel(image, 5, 0, 0, 0, 1, "Image alpha is forced to 1");
}

}  // namespace
}  // namespace toyhost::testing
