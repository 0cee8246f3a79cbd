// compareShadertoys (include/toyhost/Compare.h): two shadertoys rendered with the same settings
// and inputs and compared frame by frame. The shadertoys of tests/gl/compare/ differ in known
// ways: one constant (frame 0 on), a divergence from iTime 0.25 (frame 3 at 10 fps, bottom half),
// the mouse (while held), a buffer's alpha.
#include "GlTestSupport.h"

#include <cmath>
#include <toyhost/Compare.h>

#include "core/AtomicFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

fs::path fixture(const std::string& name) { return sourceDir() / "tests/gl/compare" / name; }

Shadertoy load(const fs::path& path) {
    Result<Shadertoy> s = Shadertoy::load(path);
    EXPECT_TRUE(s.ok()) << s.error().text();
    return *s;
}

// 40x20 at 10 fps, 6 frames; frames n at iTime n / 10.
CompareSettings small(int frames = 6) {
    CompareSettings settings;
    settings.session.width = 40;
    settings.session.height = 20;
    settings.session.fps = 10;
    settings.session.date = "2026-01-01T00:00:00";
    settings.frames = frames;
    return settings;
}

Result<CompareReport> compareOnGlThread(const fs::path& a, const fs::path& b, const CompareSettings& settings) {
    const Shadertoy first = load(a), second = load(b);
    std::optional<Result<CompareReport>> report;
    runOnGlThread([&] { report.emplace(compareShadertoys(first, second, settings)); });
    return std::move(*report);
}

TEST(Compare, TheSameShadertoyIsEqualOnEveryFrame) {
    Result<CompareReport> report = compareOnGlThread(fixture("base"), fixture("base"), small());
    ASSERT_TRUE(report.ok()) << report.error().text();
    EXPECT_TRUE(report->equal());
    EXPECT_EQ(report->width, 40);
    EXPECT_EQ(report->height, 20);
    ASSERT_EQ(report->frames.size(), 6u);
    for (const FrameDifference& f : report->frames) {
        EXPECT_TRUE(std::isinf(f.psnr)) << "frame " << f.frame;
        EXPECT_EQ(f.differingPixels, 0);
        EXPECT_NEAR(f.time, f.frame / 10.0, 1e-12);
    }
    EXPECT_TRUE(std::isinf(report->minPsnr));
}

TEST(Compare, OneConstantChangedDiffersFromFrameZeroWhereTheBandMoved) {
    CompareSettings settings = small(2);
    settings.keepDiffImages = true;
    Result<CompareReport> report = compareOnGlThread(fixture("base"), fixture("constant"), settings);
    ASSERT_TRUE(report.ok()) << report.error().text();
    EXPECT_FALSE(report->equal());
    ASSERT_TRUE(report->firstDifferingFrame);
    EXPECT_EQ(*report->firstDifferingFrame, 0);
    const FrameDifference& f = report->frames[0];
    // Blue is 1 right of x = edge: pixels x = 20..29 of 40 (uv.x = (x + 0.5) / 40) differ by 255.
    EXPECT_EQ(f.maxDiff, 255);
    EXPECT_EQ(f.differingPixels, 10 * 20);
    EXPECT_EQ(f.firstX, 20);
    EXPECT_EQ(f.firstY, 0);
    EXPECT_TRUE(std::isfinite(f.psnr));
    // 200 pixels of 800 with one sample of three off by 255: MSE = 255^2 * 200 / 2400.
    EXPECT_NEAR(f.psnr, 10.0 * std::log10(2400.0 / 200.0), 1e-9);
    ASSERT_EQ(f.diffImage.size(), 40u * 20 * 4);
    auto at = [&](int x, int y, int c) { return f.diffImage[(static_cast<std::size_t>(y) * 40 + x) * 4 + c]; };
    EXPECT_EQ(at(19, 5, 2), 0);
    EXPECT_EQ(at(20, 5, 2), 255);
    EXPECT_EQ(at(29, 19, 2), 255);
    EXPECT_EQ(at(30, 0, 2), 0);
    EXPECT_EQ(at(25, 3, 0), 0);
    EXPECT_EQ(at(25, 3, 3), 255);
}

TEST(Compare, ATimeDependentDivergenceIsFoundAtItsFrame) {
    Result<CompareReport> report = compareOnGlThread(fixture("base"), fixture("diverge"), small());
    ASSERT_TRUE(report.ok()) << report.error().text();
    ASSERT_TRUE(report->firstDifferingFrame);
    EXPECT_EQ(*report->firstDifferingFrame, 3) << "iTime 0.3 is the first frame at or after 0.25";
    for (int n = 0; n < 3; ++n) EXPECT_TRUE(std::isinf(report->frames[n].psnr)) << "frame " << n;
    for (int n = 3; n < 6; ++n) EXPECT_TRUE(std::isfinite(report->frames[n].psnr)) << "frame " << n;
    // The bottom half differs: with the top row first, the first differing row is row 10 of 20.
    EXPECT_EQ(report->frames[3].firstX, 0);
    EXPECT_EQ(report->frames[3].firstY, 10);
    EXPECT_EQ(report->frames[3].differingPixels, 40 * 10);
}

TEST(Compare, ToleranceDecidesEquality) {
    CompareSettings settings = small(1);
    settings.tolerance.maxDiff = 255;
    Result<CompareReport> loose = compareOnGlThread(fixture("base"), fixture("constant"), settings);
    ASSERT_TRUE(loose.ok()) << loose.error().text();
    EXPECT_TRUE(loose->equal());
    settings.tolerance = {};
    settings.tolerance.minPsnr = 11.0;  // the frame's PSNR is 10 log10(12) = 10.8 dB
    Result<CompareReport> strict = compareOnGlThread(fixture("base"), fixture("constant"), settings);
    ASSERT_TRUE(strict.ok());
    EXPECT_FALSE(strict->equal());
    settings.tolerance.minPsnr = 10.0;
    EXPECT_TRUE(compareOnGlThread(fixture("base"), fixture("constant"), settings)->equal());
}

TEST(Compare, BothGetTheSameMouseScript) {
    // Without input the mouse shader equals base; with the button down from frame 2, it differs
    // from frame 2.
    EXPECT_TRUE(compareOnGlThread(fixture("base"), fixture("mouse"), small(4))->equal());
    CompareSettings settings = small(4);
    settings.session.mouseScript = fixture("mouse-down.json");
    Result<CompareReport> scripted = compareOnGlThread(fixture("base"), fixture("mouse"), settings);
    ASSERT_TRUE(scripted.ok()) << scripted.error().text();
    ASSERT_TRUE(scripted->firstDifferingFrame);
    EXPECT_EQ(*scripted->firstDifferingFrame, 2);
    // The same with events given by the program.
    CompareSettings programmed = small(4);
    programmed.input = [](int frame, double) {
        return frame == 1 ? std::vector<InputEvent>{InputEvent::mouseDown(3, 4)} : std::vector<InputEvent>{};
    };
    Result<CompareReport> byProgram = compareOnGlThread(fixture("base"), fixture("mouse"), programmed);
    ASSERT_TRUE(byProgram.ok());
    EXPECT_EQ(byProgram->firstDifferingFrame.value_or(-1), 1);
}

TEST(Compare, ABufferIsComparedWithItsAlpha) {
    CompareSettings settings = small(1);
    EXPECT_TRUE(compareOnGlThread(fixture("buffer"), fixture("buffer-alpha"), settings)->equal())
        << "Image forces alpha to 1: the Image passes are equal";
    settings.pass = "Buffer A";
    Result<CompareReport> report = compareOnGlThread(fixture("buffer"), fixture("buffer-alpha"), settings);
    ASSERT_TRUE(report.ok()) << report.error().text();
    EXPECT_FALSE(report->equal());
    EXPECT_EQ(report->frames[0].maxDiff, 128 - 64);
    EXPECT_EQ(report->frames[0].differingPixels, 40 * 20);
}

TEST(Compare, OnFrameSeesBothFramesAndCanStop) {
    CompareSettings settings = small(6);
    settings.diffImages = true;
    int calls = 0;
    settings.onFrame = [&](const ComparedFrame& f) {
        ++calls;
        EXPECT_EQ(f.a.size(), 40u * 20 * 4);
        EXPECT_EQ(f.b.size(), 40u * 20 * 4);
        EXPECT_EQ(f.diffImage.empty(), f.difference.withinTolerance);
        return f.difference.frame < 3;  // stop after the first differing frame
    };
    Result<CompareReport> report = compareOnGlThread(fixture("base"), fixture("diverge"), settings);
    ASSERT_TRUE(report.ok()) << report.error().text();
    EXPECT_EQ(calls, 4);
    EXPECT_EQ(report->frames.size(), 4u);
    EXPECT_TRUE(report->frames[3].diffImage.empty()) << "kept only with keepDiffImages";
}

TEST(Compare, ProblemsAreErrorsNamingTheirPlace) {
    CompareSettings settings = small(1);
    settings.pass = "Buffer A";
    Result<CompareReport> noPass = compareOnGlThread(fixture("base"), fixture("buffer"), settings);
    ASSERT_FALSE(noPass.ok());
    EXPECT_NE(noPass.error().text().find("base"), std::string::npos) << noPass.error().text();
    settings.pass = "Sound";
    EXPECT_FALSE(compareOnGlThread(fixture("base"), fixture("base"), settings).ok());

    settings = small(1);
    Result<CompareReport> broken = compareOnGlThread(fixture("base"), fixture("broken"), settings);
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().text().find("colour"), std::string::npos) << broken.error().text();

    settings.session.mouseScript = fixture("no-such-script.json");
    Result<CompareReport> noScript = compareOnGlThread(fixture("base"), fixture("base"), settings);
    ASSERT_FALSE(noScript.ok());
    EXPECT_NE(noScript.error().text().find("no-such-script.json"), std::string::npos) << noScript.error().text();
}

// The acceptance: an export against the folder `toyhost import` made from it is equal.
TEST(Compare, AnExportEqualsItsImportedFolder) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/MdXyzX.json");
    const fs::path dir = testOutputDir() / "compare/imported-ocean";
    fs::remove_all(dir);
    auto imported = runToyhost("import " + (sharedDir() / "shadertoys/MdXyzX/MdXyzX.json").string() + " " + dir.string());
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    CompareSettings settings = small(3);
    settings.session.width = 64;
    settings.session.height = 36;
    Result<CompareReport> report = compareOnGlThread(sharedDir() / "shadertoys/MdXyzX/MdXyzX.json", dir, settings);
    ASSERT_TRUE(report.ok()) << report.error().text();
    EXPECT_TRUE(report->equal());
    EXPECT_TRUE(std::isinf(report->minPsnr));

    // One constant of the port changed (the waves' drag): a finite PSNR from frame 0.
    Result<std::string> code = readTextFile(dir / "image.glsl");
    ASSERT_TRUE(code.ok());
    const std::string before = "#define DRAG_MULT 0.38", after = "#define DRAG_MULT 0.39";
    const std::size_t at = code->find(before);
    ASSERT_NE(at, std::string::npos) << "the ocean's DRAG_MULT line";
    writeFile(dir / "image.glsl", code->replace(at, before.size(), after));
    Result<CompareReport> changed = compareOnGlThread(sharedDir() / "shadertoys/MdXyzX/MdXyzX.json", dir, settings);
    ASSERT_TRUE(changed.ok()) << changed.error().text();
    ASSERT_TRUE(changed->firstDifferingFrame);
    EXPECT_EQ(*changed->firstDifferingFrame, 0);
    EXPECT_TRUE(std::isfinite(changed->frames[0].psnr));
    EXPECT_GT(changed->frames[0].psnr, 15.0) << "the same scene, slightly different waves";
}

}  // namespace
}  // namespace toyhost::testing
