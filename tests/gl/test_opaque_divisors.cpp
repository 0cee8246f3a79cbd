// A division by a zero Mesa's compiler can see gives the browser's IEEE value on every run (issue
// 42). Mesa 22.3 folded such divisions (a literal 0.0, `e - e`, smoothstep(e, e, x), a constant 0
// passed to a function that divides by it) from uninitialised memory: 0, NaN or random values,
// different from run to run (webref probe zi_loop gave 2-3 different frames in 6 runs). The
// browser's GPU divides at run time: x / 0 is +-inf, 0 / 0 NaN. shader/OpaqueDivisors hides every
// divisor behind a uniform 0 (its bits XORed with it), so llvmpipe divides at run time too.
#include "GlTestSupport.h"

#include <toyhost/Session.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace toyhost::testing {
namespace {

// The webref probe zi_loop's Image, as it is written there (../shared/webref/probes/zi_loop.json):
// smin with k = 0 divides by the constant 0 after inlining.
const char* const kZiLoop =
    "float smin(float a, float b, float k) { float h = clamp(0.5 + 0.5*(a-b)/k, 0.0, 1.0); return mix(a, b, h) - k*h*(1.0-h); }\n"
    "float g(float x) { float r; for (int i = 0; i < 2; ++i) { r = smin(r, x - 0.1*float(i), 0.); } return r; }\n"
    "void mainImage(out vec4 o, in vec2 fc) { float v = g(fc.x / iResolution.x - 0.5); o = vec4(v + 0.5, isnan(v) ? 1.0 : "
    "0.0, isinf(v) ? 1.0 : 0.0, 1.0); }";

constexpr int kRuns = 10;
constexpr int kWidth = 8;

// The frames of `code` over kRuns runs, each checked equal to the first.
std::vector<std::uint8_t> sameOnEveryRun(const std::string& name, const std::string& code) {
    const std::filesystem::path dir = freshOutputDir("gl/opaque-divisors/" + name);
    std::vector<std::uint8_t> first;
    for (int run = 0; run < kRuns; ++run) {
        const std::vector<std::uint8_t> pixels = renderImageOnce(dir / std::to_string(run), code, kWidth, 1);
        EXPECT_EQ(pixels.size(), 4u * kWidth) << "run " << run;
        if (run == 0) first = pixels;
        else EXPECT_EQ(pixels, first) << "run " << run << " differs from run 0";
    }
    return first;
}

TEST(OpaqueDivisorsGl, ZiLoopIsTheSameOnEveryRunAndTheBrowsersMinimum) {
    const std::vector<std::uint8_t> pixels = sameOnEveryRun("zi-loop", kZiLoop);
    ASSERT_EQ(pixels.size(), 4u * kWidth);
    // The browser's IEEE path: (a - b) / 0 is +inf (h = 1: b) or -inf (h = 0: a), never NaN here
    // (a == b at no pixel), so g(x) = min(0, x - 0.1): red (v + 0.5) * 255, no NaN, no inf.
    for (int p = 0; p < kWidth; ++p) {
        SCOPED_TRACE(p);
        const double x = (p + 0.5) / kWidth - 0.5;
        const double red = std::clamp(std::min(0.0, x - 0.1) + 0.5, 0.0, 1.0) * 255.0;
        if (red == 127.5) EXPECT_NEAR(pixels[4 * p], 127.5, 0.5);  // v = 0: a tie either side rounds
        else EXPECT_EQ(pixels[4 * p], static_cast<int>(std::lround(red)));
        EXPECT_EQ(pixels[4 * p + 1], 0) << "NaN";
        EXPECT_EQ(pixels[4 * p + 2], 0) << "inf";
    }
}

TEST(OpaqueDivisorsGl, SmoothstepWithEqualEdgesIsAStepAsInTheBrowser) {
    // smoothstep(e, e, x) divides x - e by e - e = 0 (after inlining, a constant): -inf below e
    // (clamped to 0), +inf above (1). x runs 0, 0.25, ..., 1.75 over the pixels; e = 0.5 is met
    // at pixel 2, where the division is 0 / 0 (NaN); that pixel is only checked to be the same on
    // every run.
    const std::vector<std::uint8_t> pixels = sameOnEveryRun(
        "smoothstep",
        "float st(float e, float x) { return smoothstep(e, e, x); }\n"
        "void mainImage(out vec4 o, in vec2 f) { float x = floor(f.x) / 4.0; float s = st(0.5, x);\n"
        "  o = vec4(s, isnan(s) ? 1.0 : 0.0, isinf(s) ? 1.0 : 0.0, 1.0); }\n");
    ASSERT_EQ(pixels.size(), 4u * kWidth);
    for (int p = 0; p < kWidth; ++p) {
        if (p == 2) continue;
        SCOPED_TRACE(p);
        EXPECT_EQ(pixels[4 * p], p < 2 ? 0 : 255);
        EXPECT_EQ(pixels[4 * p + 1], 0);
        EXPECT_EQ(pixels[4 * p + 2], 0);
    }
}

}  // namespace
}  // namespace toyhost::testing
