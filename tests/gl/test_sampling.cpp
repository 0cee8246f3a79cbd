// Supersampling and motion blur (timing/SamplePattern.h, render/SampleAccumulator.h) checked
// against what they must equal: a stateless picture supersampled 4x4 equals the same picture
// rendered 4x larger and box-averaged (the sample positions are the same); motion blur of a colour
// linear in iTime equals its analytic average over the shutter interval; one sample is the site's
// pixels byte for byte; buffers do not depend on the sample count (Image drawn in the same
// sessions); `run` and the C++ Session give
// the same frames. Python's: python/tests/test_sampling.py.
#include "GlTestSupport.h"

#include <cmath>

#include <toyhost/Session.h>

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kProbe = sourceDir() / "shadertoys/sampling-probe";
constexpr const char* kDate = "2024-01-01T12:00:00";

// Renders `frames` frames with `settings` through the library and reads the last one's passes
// (RGBA8, rows top first) into `reads` (pass name, where).
void render(const fs::path& target, SessionSettings settings, int frames,
            std::initializer_list<std::pair<const char*, std::vector<std::uint8_t>*>> reads) {
    Result<Shadertoy> shadertoy = Shadertoy::load(target);
    EXPECT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    if (!shadertoy) return;
    if (!settings.date) settings.date = kDate;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*shadertoy, settings);
        ASSERT_TRUE(session.ok()) << session.error().text();
        for (int n = 0; n < frames; ++n) ASSERT_TRUE((*session)->step().ok());
        for (const auto& [pass, pixels] : reads) {
            pixels->resize(static_cast<std::size_t>((*session)->width()) * (*session)->height() * 4);
            ASSERT_TRUE((*session)->read(pass, *pixels).ok()) << pass;
        }
    });
}

// The last of `frames` frames' Image.
std::vector<std::uint8_t> render(const fs::path& target, SessionSettings settings, int frames = 1) {
    std::vector<std::uint8_t> pixels;
    render(target, std::move(settings), frames, {{"Image", &pixels}});
    return pixels;
}

SessionSettings sized(int width, int height) {
    SessionSettings s;
    s.width = width;
    s.height = height;
    return s;
}

double psnr(const std::vector<double>& a, const std::vector<double>& b) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha is 1 in both
        sum += (a[i] - b[i]) * (a[i] - b[i]);
        ++n;
    }
    return sum == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / (sum / static_cast<double>(n)));
}

TEST(Sampling, Supersample4EqualsTheBoxAverageOfARender4xLarger) {
    constexpr int w = 64, h = 36, n = 4;
    SessionSettings small = sized(w, h);
    small.supersample = n;
    small.sampleSpace = "display";  // the box of display values (linear light: test_sampling_average.cpp)
    const std::vector<std::uint8_t> supersampled = render(kProbe, small);
    const std::vector<std::uint8_t> large = render(kProbe, sized(w * n, h * n));
    const std::vector<std::uint8_t> single = render(kProbe, sized(w, h));
    ASSERT_EQ(supersampled.size(), static_cast<std::size_t>(w) * h * 4);
    ASSERT_EQ(large.size(), supersampled.size() * n * n);
    std::vector<double> boxed(supersampled.size()), ours(supersampled.begin(), supersampled.end()),
        one(single.begin(), single.end());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 4; ++c) {
                double sum = 0;
                for (int j = 0; j < n; ++j)
                    for (int i = 0; i < n; ++i)
                        sum += large[((static_cast<std::size_t>(y) * n + j) * w * n + x * n + i) * 4 + c];
                boxed[(static_cast<std::size_t>(y) * w + x) * 4 + c] = sum / (n * n);
            }
    const double matched = psnr(ours, boxed);
    EXPECT_GE(matched, 45.0);
    // The comparison can fail: the site's single sample is far from the box average (edges).
    EXPECT_LT(psnr(one, boxed), 35.0);
    EXPECT_GT(matched, psnr(one, boxed) + 10);
}

TEST(Sampling, MotionBlurOfAColourLinearInTimeIsItsShutterAverage) {
    // Blue is 0.05 * iTime: over the interval [t, t + shutter/360 * dt] its average is
    // 0.05 * (t + shutter/720 * dt).
    for (double shutter : {180.0, 360.0, 90.0}) {
        SessionSettings s = sized(16, 8);
        s.fps = 2;  // dt = 0.5 s: a wide interval
        s.startTime = 3;
        s.motionBlur = 8;
        s.shutterDegrees = shutter;
        s.sampleSpace = "display";  // the average of the code values, as computed here
        const std::vector<std::uint8_t> blurred = render(kProbe, s, 2);  // frame 1: t = 3.5
        ASSERT_FALSE(blurred.empty());
        const double expected = 0.05 * (3.5 + shutter / 720.0 * 0.5) * 255.0;
        for (std::size_t i = 2; i < blurred.size(); i += 4)
            ASSERT_LE(std::abs(blurred[i] - expected), 1.0) << "shutter " << shutter << ": blue " << int(blurred[i])
                                                           << ", expected " << expected;
    }
    // Without blur the frame shows its own instant: 0.05 * 3.5 = 0.175 (44.6 of 255).
    SessionSettings still = sized(16, 8);
    still.fps = 2;
    still.startTime = 3;
    EXPECT_EQ(render(kProbe, still, 2)[2], 45);
}

TEST(Sampling, OneSampleIsTheSitesPixelsByteForByte) {
    SessionSettings one = sized(96, 54);
    one.supersample = 1;
    one.motionBlur = 1;
    one.sampleSpace = "linear";  // a space averages nothing in one sample
    const fs::path ocean = sourceDir() / "shadertoys/ocean";
    EXPECT_EQ(render(ocean, one, 2), render(ocean, sized(96, 54), 2));
}

TEST(Sampling, BuffersDoNotDependOnTheSampleCount) {
    // Mountains & Lakes' simulation state (Buffer A) after a few frames, with and without 2x2
    // supersampling and motion blur of Image, read from the same sessions whose Image is drawn
    // with the samples (issue 44: a check that skips Image renders no sample): identical.
    const fs::path lakes = sourceDir() / "shadertoys/mountains-lakes";
    SessionSettings sampled = sized(96, 54);
    sampled.supersample = 2;
    sampled.motionBlur = 2;
    std::vector<std::uint8_t> plain, withSamples, plainImage, sampledImage;
    render(lakes, sized(96, 54), 4, {{"Buffer A", &plain}, {"Image", &plainImage}});
    render(lakes, sampled, 4, {{"Buffer A", &withSamples}, {"Image", &sampledImage}});
    ASSERT_FALSE(plain.empty());
    EXPECT_EQ(plain, withSamples);
    // While the picture itself, drawn in those sessions, changes.
    ASSERT_FALSE(sampledImage.empty());
    EXPECT_NE(plainImage, sampledImage);
}

TEST(Sampling, RunAndTheCppSessionGiveTheSameFrames) {
    const fs::path dir = freshOutputDir("sampling-surfaces");
    const CommandResult cli = runToyhost("run " + kProbe.string() +
                                         " --headless --size 40x24 --frames 3 --fps 4 --date " + kDate +
                                         " --supersample 3 --motion-blur 2 --shutter 270 --dither --quiet --out " +
                                         (dir / "f_%d.png").string());
    ASSERT_EQ(cli.exitCode, 0) << cli.output;
    Result<Image8> png = readPng(dir / "f_2.png");
    ASSERT_TRUE(png.ok()) << png.error().text();
    SessionSettings s = sized(40, 24);
    s.fps = 4;
    s.supersample = 3;
    s.motionBlur = 2;
    s.shutterDegrees = 270;
    s.dither = true;
    std::vector<std::uint8_t> ours = render(kProbe, s, 3);
    ASSERT_EQ(ours.size(), png->rgba.size());
    // Image8 is bottom row first.
    const std::size_t row = 40 * 4;
    for (int y = 0; y < 24; ++y)
        ASSERT_TRUE(std::equal(ours.begin() + static_cast<std::ptrdiff_t>(y * row),
                               ours.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                               png->rgba.begin() + static_cast<std::ptrdiff_t>((23 - y) * row)))
            << "row " << y;
    // The dither is there: without it the same frame differs.
    s.dither = false;
    EXPECT_NE(render(kProbe, s, 3), ours);
}

TEST(Sampling, CompareRendersBothSidesWithTheSamples) {
    const fs::path dir = freshOutputDir("sampling-compare");
    const std::string common = " --size 40x24 --fps 4 --date " + std::string(kDate) + " --supersample 2 --motion-blur 3";
    const CommandResult run = runToyhost("run " + kProbe.string() + " --headless --quiet --frames 2" + common +
                                         " --out " + (dir / "run_%d.png").string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const CommandResult compare = runToyhost("compare " + kProbe.string() + " " + kProbe.string() + " --frames 2" +
                                             common + " --frames-out " + (dir / "pairs").string());
    ASSERT_EQ(compare.exitCode, 0) << compare.output;
    Result<Image8> ran = readPng(dir / "run_1.png");
    Result<Image8> a = readPng(dir / "pairs/a_0001.png");
    ASSERT_TRUE(ran.ok() && a.ok()) << compare.output;
    EXPECT_TRUE(ran->rgba == a->rgba);
    // Without the samples compare's frame differs (the flags reached the sessions).
    const CommandResult plain = runToyhost("compare " + kProbe.string() + " " + kProbe.string() +
                                           " --frames 2 --size 40x24 --fps 4 --date " + kDate + " --frames-out " +
                                           (dir / "plain").string());
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    Result<Image8> one = readPng(dir / "plain/a_0001.png");
    ASSERT_TRUE(one.ok());
    EXPECT_FALSE(one->rgba == a->rgba);
}

TEST(Sampling, ValuesOutOfRangeAreRefusedNamingTheSetting) {
    Result<Shadertoy> probe = Shadertoy::load(kProbe);
    ASSERT_TRUE(probe.ok());
    auto refused = [&](SessionSettings s) {
        std::string text;
        runOnGlThread([&] {
            Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe, s);
            if (!session) text = session.error().first().field + ": " + session.error().first().message;
        });
        return text;
    };
    SessionSettings s = sized(8, 8);
    s.supersample = 0;
    EXPECT_EQ(refused(s).rfind("supersample: must be 1 to 16", 0), 0u) << refused(s);
    s.supersample = 16;
    s.motionBlur = 17;
    EXPECT_NE(refused(s).find("4352 draws a frame, more than 4096"), std::string::npos) << refused(s);
    s = sized(8, 8);
    s.shutterDegrees = 0;
    EXPECT_EQ(refused(s).rfind("shutter:", 0), 0u) << refused(s);
    s = sized(8, 8);
    s.dither = true;
    EXPECT_EQ(refused(s).rfind("dither:", 0), 0u) << refused(s);
    // A shutter or its offset without motion blur would be ignored: refused as the dither is
    // (issue 46), and accepted with it.
    s = sized(8, 8);
    s.shutterDegrees = 90;
    EXPECT_EQ(refused(s), "shutter: sets the interval of motion blur: give motion_blur too");
    s.motionBlur = 2;
    EXPECT_EQ(refused(s), "");
    s = sized(8, 8);
    s.shutterOffset = "centre";
    EXPECT_EQ(refused(s).rfind("shutter_offset:", 0), 0u) << refused(s);
    const CommandResult shutter = runToyhost("run " + kProbe.string() + " --headless --size 8x8 --shutter 90");
    EXPECT_EQ(shutter.exitCode, 2) << shutter.output;
    EXPECT_NE(shutter.output.find("--shutter"), std::string::npos) << shutter.output;
    EXPECT_NE(shutter.output.find("sets the interval of motion blur"), std::string::npos) << shutter.output;
    const CommandResult offset =
        runToyhost("run " + kProbe.string() + " --headless --size 8x8 --motion-blur 2 --shutter-offset middle");
    EXPECT_EQ(offset.exitCode, 2) << offset.output;
    EXPECT_NE(offset.output.find("--shutter-offset"), std::string::npos) << offset.output;
    const CommandResult cli = runToyhost("run " + kProbe.string() + " --headless --size 8x8 --motion-blur 0");
    EXPECT_EQ(cli.exitCode, 2) << cli.output;
    EXPECT_NE(cli.output.find("--motion-blur"), std::string::npos) << cli.output;
}

}  // namespace
}  // namespace toyhost::testing
