// How the samples of supersampling and motion blur are averaged (render/SampleAccumulator.h,
// issue 44): each draw renders to a float target and the draws are averaged in float and quantised
// once, so --dither breaks up slow bands; the average is in linear light unless --sample-space
// display (arithmetic checks on half- and quarter-covered pixels, a thin bright line keeps its
// light); display values stay today's (the box average of a 4x render, within a level); every draw
// has its own instant of the shutter, so a fast bar leaves one streak, placed by the shutter
// offset; a draw that discards adds the preserved canvas. Values are checked against numbers computed here; no golden images.
#include "GlTestSupport.h"

#include <algorithm>
#include <cmath>

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// The last of `frames` frames of the Image-only shadertoy `code` with `settings` (width x height
// set), RGBA8 rows as read() gives them.
std::vector<std::uint8_t> renderCode(const std::string& name, const std::string& code, SessionSettings settings,
                                     int frames = 1) {
    const fs::path dir = freshOutputDir("sampling-average/" + name);
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", code);
    Result<Shadertoy> toy = Shadertoy::load(dir);
    EXPECT_TRUE(toy.ok()) << toy.error().text();
    if (!toy) return {};
    if (!settings.date) settings.date = "2024-01-01T12:00:00";
    std::vector<std::uint8_t> pixels;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*toy, settings);
        ASSERT_TRUE(session.ok()) << session.error().text();
        pixels.resize(static_cast<std::size_t>(*settings.width) * *settings.height * 4);
        for (int n = 0; n < frames; ++n) ASSERT_TRUE((*session)->step().ok());
        ASSERT_TRUE((*session)->read("Image", pixels).ok());
    });
    return pixels;
}

SessionSettings sampled(int width, int height, int supersample, const char* space = nullptr) {
    SessionSettings s;
    s.width = width;
    s.height = height;
    s.supersample = supersample;
    if (space) s.sampleSpace = space;
    return s;
}

// The sRGB transfer function and its inverse (IEC 61966-2-1), on [0, 1].
double toLinear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double toSrgb(double v) { return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1 / 2.4) - 0.055; }

// The longest run of equal red values along row `y` of a `width`-wide picture.
int longestRun(const std::vector<std::uint8_t>& pixels, int width, int y) {
    int longest = 0, run = 0;
    for (int x = 0; x < width; ++x) {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 4;
        run = x > 0 && pixels[i] == pixels[i - 4] ? run + 1 : 1;
        longest = std::max(longest, run);
    }
    return longest;
}

// Half of each pixel white (the samples at x + 0.25 of 2 x 2), or a quarter (x and y + 0.25).
constexpr const char* kHalf =
    "void mainImage(out vec4 c, in vec2 p) { c = vec4(vec3(fract(p.x) < 0.5 ? 1.0 : 0.0), 1.0); }\n";
constexpr const char* kQuarter = "void mainImage(out vec4 c, in vec2 p) {\n"
                                 "    c = vec4(vec3(fract(p.x) < 0.5 && fract(p.y) < 0.5 ? 1.0 : 0.0), 1.0);\n}\n";

TEST(SamplingAverage, ACoveredFractionAveragesInLinearLightByDefaultAndInDisplayValuesWhenAsked) {
    // Half covered: 0.5 of the light is sRGB 0.7354 (187.5: 188); the display values give 127.5.
    const std::vector<std::uint8_t> linear = renderCode("half", kHalf, sampled(8, 4, 2));
    const std::vector<std::uint8_t> display = renderCode("half", kHalf, sampled(8, 4, 2, "display"));
    ASSERT_EQ(linear.size(), 8u * 4 * 4);
    ASSERT_EQ(display.size(), linear.size());
    EXPECT_EQ(std::lround(toSrgb(0.5) * 255), 188);
    for (std::size_t i = 0; i < linear.size(); i += 4) {
        ASSERT_EQ(linear[i], 188) << "pixel " << i / 4;
        ASSERT_EQ(linear[i + 3], 255);
        ASSERT_GE(display[i], 127) << "pixel " << i / 4;
        ASSERT_LE(display[i], 128) << "pixel " << i / 4;
    }
    // A quarter: sRGB(0.25) = 0.5371 (137.0); display 63.75 (64).
    const std::vector<std::uint8_t> quarterLinear = renderCode("quarter", kQuarter, sampled(8, 4, 2));
    const std::vector<std::uint8_t> quarterDisplay = renderCode("quarter", kQuarter, sampled(8, 4, 2, "display"));
    EXPECT_EQ(std::lround(toSrgb(0.25) * 255), 137);
    for (std::size_t i = 0; i < quarterLinear.size(); i += 4) {
        ASSERT_EQ(quarterLinear[i], 137) << "pixel " << i / 4;
        ASSERT_EQ(quarterDisplay[i], 64) << "pixel " << i / 4;
    }
    // A word that is not a space is refused naming the setting.
    Result<Shadertoy> toy = Shadertoy::load(testOutputDir() / "sampling-average/half");
    ASSERT_TRUE(toy.ok());
    std::string refused;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> s = Session::createHeadless(*toy, sampled(8, 4, 2, "gamma"));
        if (!s) refused = s.error().first().field + ": " + s.error().first().message;
    });
    EXPECT_EQ(refused.rfind("sample_space: must be linear or display", 0), 0u) << refused;
}

TEST(SamplingAverage, AThinBrightLineKeepsItsLightInLinearLight) {
    // A line 0.3 px wide across a black canvas: in display values its pixels get 30% of white's
    // code value, far darker than 30% of its light (the glints the issue found 5-20 levels dark).
    const std::string line = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    c = vec4(vec3(abs(p.x - 10.0 - 0.37 * p.y) < 0.15 ? 1.0 : 0.0), 1.0);\n}\n";
    const std::vector<std::uint8_t> linear = renderCode("line", line, sampled(32, 16, 8));
    const std::vector<std::uint8_t> display = renderCode("line", line, sampled(32, 16, 8, "display"));
    ASSERT_EQ(linear.size(), display.size());
    double lightLinear = 0, lightDisplay = 0, codeDisplay = 0;
    for (std::size_t i = 0; i < linear.size(); i += 4) {
        ASSERT_GE(linear[i], display[i]) << "pixel " << i / 4;  // never darker
        lightLinear += toLinear(linear[i] / 255.0);
        lightDisplay += toLinear(display[i] / 255.0);
        codeDisplay += display[i] / 255.0;
    }
    // The line's light: 0.3 px x 16 rows = 4.8 pixels of white; linear keeps it within rounding.
    EXPECT_NEAR(lightLinear, 4.8, 0.25);
    EXPECT_LT(lightDisplay, 0.6 * lightLinear);  // display values lose most of it
    EXPECT_NEAR(codeDisplay, 4.8, 0.25);         // (they keep the code values' sum instead)
}

// A 4x render box-averaged, in display values (what --sample-space display did and does) or in
// linear light (decoded, averaged, encoded): the truths of --supersample 4 on a stateless shader.
TEST(SamplingAverage, Supersample4MatchesThe4xRenderAveragedInTheSameSpace) {
    const std::string probe = "void mainImage(out vec4 c, in vec2 p) {\n"
                              "    vec2 uv = p / iResolution.xy;\n"
                              "    float r = length(uv - 0.5) * 40.0;\n"
                              "    c = vec4(0.5 + 0.5 * sin(r * r * 0.2), step(0.5, fract(uv.x * 7.0 + uv.y * 3.0)),\n"
                              "             fract(uv.y * 5.0), 1.0);\n}\n";
    constexpr int w = 48, h = 27, n = 4;
    const std::vector<std::uint8_t> large = renderCode("box", probe, sampled(w * n, h * n, 1));
    const std::vector<std::uint8_t> linear = renderCode("box", probe, sampled(w, h, n));
    const std::vector<std::uint8_t> display = renderCode("box", probe, sampled(w, h, n, "display"));
    ASSERT_EQ(large.size(), linear.size() * n * n);
    double worstDisplay = 0, worstLinear = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                double code = 0, light = 0;
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i) {
                        const int v = large[((static_cast<std::size_t>(y) * n + j) * w * n + x * n + i) * 4 + c];
                        code += v;
                        light += toLinear(v / 255.0);
                    }
                const std::size_t at = (static_cast<std::size_t>(y) * w + x) * 4 + c;
                worstDisplay = std::max(worstDisplay, std::abs(display[at] - code / (n * n)));
                worstLinear = std::max(worstLinear, std::abs(linear[at] - toSrgb(light / (n * n)) * 255));
            }
    // Display: today's (the average of 8-bit draws) within rounding: the draws are no longer
    // rounded before they are summed, which moves the average by less than half a level.
    EXPECT_LE(worstDisplay, 1.0);
    // Linear: the truth's draws were rounded to 8 bits before decoding; ours were not.
    EXPECT_LE(worstLinear, 2.0);
}

TEST(SamplingAverage, DitherOfAFloatAverageBreaksUpSlowBands) {
    // The issue's ramp: 15 levels over 640 pixels, bands of about 43 pixels in one sample. Every
    // draw used to be rounded, so the average and its dither only changed the band edges (runs of
    // 43 remained).
    const std::string ramp = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    c = vec4(vec3((120.0 + 15.0 * p.x / iResolution.x) / 255.0), 1.0);\n}\n";
    constexpr int w = 640, h = 8;
    SessionSettings one = sampled(w, h, 1);
    SessionSettings dithered = sampled(w, h, 4);
    dithered.dither = true;
    const std::vector<std::uint8_t> bands = renderCode("ramp", ramp, one);
    const std::vector<std::uint8_t> smooth = renderCode("ramp", ramp, dithered);
    ASSERT_EQ(bands.size(), smooth.size());
    const int band = longestRun(bands, w, 0);
    EXPECT_GE(band, 42);
    // A row of the 8x8 Bayer matrix spans 2/3 of a level (its even and odd columns two clusters),
    // so runs of about a third of a band plus a period remain: 22 pixels here, at most 2/3 of a band.
    for (int y = 0; y < h; ++y)
        EXPECT_LE(longestRun(smooth, w, y), 2 * band / 3) << "row " << y << " (bands " << band << ")";
    // Without the dither the float average still rounds into bands.
    SessionSettings plain = sampled(w, h, 4);
    EXPECT_GE(longestRun(renderCode("ramp", ramp, plain), w, 0), band - 2);
    // The same pixels every time.
    EXPECT_EQ(renderCode("ramp", ramp, dithered), smooth);
}

// An Image that discards keeps the site's preserved canvas where it discards: with samples, a draw
// that discards adds the canvas's pixel (the previous frame's average), not what an earlier draw
// left in the float target (SampleAccumulator::seed).
TEST(SamplingAverage, ADiscardingDrawAddsThePreservedCanvas) {
    // Frame 0: half of each pixel white (188 in linear light); frame 1: the left half discards
    // in every draw, the right half is black.
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    if (iFrame == 0) { c = vec4(vec3(fract(p.x) < 0.5 ? 1.0 : 0.0), 1.0); return; }\n"
                             "    if (p.x < 4.0) discard;\n"
                             "    c = vec4(0.0, 0.0, 0.0, 1.0);\n}\n";
    const std::vector<std::uint8_t> pixels = renderCode("discard", code, sampled(8, 2, 2), 2);
    ASSERT_EQ(pixels.size(), 8u * 2 * 4);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 8; ++x)
            EXPECT_EQ(pixels[(static_cast<std::size_t>(y) * 8 + x) * 4], x < 4 ? 188 : 0) << x << "," << y;
}

// A 2 px bar at 3000 px/s, 24 fps, shutter 180: 62.5 px of travel while the shutter is open.
constexpr const char* kBar = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    float x = 48.0 + 3000.0 * iTime;\n"
                             "    c = vec4(vec3(p.x >= x && p.x < x + 2.0 ? 1.0 : 0.0), 1.0);\n}\n";

SessionSettings bar(int supersample, int motionBlur, const char* offset = nullptr) {
    SessionSettings s = sampled(176, 4, supersample);
    s.fps = 24;
    s.motionBlur = motionBlur;
    if (offset) s.shutterOffset = offset;
    return s;
}

struct Streak {
    int first = -1, last = -1, widestGap = 0;
};
Streak streakOf(const std::vector<std::uint8_t>& pixels, int width) {
    Streak s;
    int gap = 0;
    for (int x = 0; x < width; ++x) {
        if (pixels[static_cast<std::size_t>(x) * 4] == 0) {
            ++gap;
            continue;
        }
        if (s.first < 0) s.first = x;
        else s.widestGap = std::max(s.widestGap, gap);
        s.last = x;
        gap = 0;
    }
    return s;
}

TEST(SamplingAverage, EveryDrawAtItsOwnInstantMakesOneStreak) {
    const Streak stratified = streakOf(renderCode("bar", kBar, bar(4, 8)), 176);
    EXPECT_LE(stratified.widestGap, 1) << stratified.first << ".." << stratified.last;
    EXPECT_EQ(stratified.first, 48);
    EXPECT_NEAR(stratified.last, 112, 1);
    // Eight instants alone leave eight copies (the comparison can fail).
    EXPECT_GE(streakOf(renderCode("bar", kBar, bar(1, 8)), 176).widestGap, 4);
    // The shutter offset moves the streak (62.5 px long; the bar is at 48 px at the frame's time):
    // centred on the frame's time, or ending at it.
    const Streak centre = streakOf(renderCode("bar", kBar, bar(4, 8, "centre")), 176);
    EXPECT_NEAR(centre.first, 17, 1);
    EXPECT_NEAR(centre.last, 81, 1);
    EXPECT_LE(centre.widestGap, 1);
    const Streak close = streakOf(renderCode("bar", kBar, bar(4, 8, "close")), 176);
    EXPECT_NEAR(close.last, 49, 1);
    EXPECT_LE(close.widestGap, 1);
}

}  // namespace
}  // namespace toyhost::testing
