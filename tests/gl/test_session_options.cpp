// SessionOptions and prepareSession: defaults come from one place, and what a run cannot do is refused
// before any GL work, with the usage code the CLI turns into exit status 2.
#include "GlTestSupport.h"

#include "core/Defaults.h"
#include "session/SessionOptions.h"

namespace toyhost::testing {
namespace {

SessionOptions probeOptions() {
    SessionOptions options;
    options.target = sourceDir() / "shadertoys/pingpong-probe";
    options.settings.width = 8;
    options.settings.height = 8;
    return options;
}

TEST(SessionOptions, AbsentFieldsTakeTheDefaultsAndGivenOnesStay) {
    const SessionOptions filled = withDefaults(SessionOptions{});
    EXPECT_EQ(*filled.settings.width, defaults::kCanvasWidth);
    EXPECT_EQ(*filled.settings.height, defaults::kCanvasHeight);
    EXPECT_EQ(*filled.frames, defaults::kFrames);
    EXPECT_EQ(*filled.settings.fps, defaults::kFps);
    EXPECT_EQ(*filled.captureEvery, defaults::kCaptureEvery);
    EXPECT_EQ(*filled.pngLevel, defaults::kPngLevel);
    EXPECT_EQ(*filled.captureMemoryBytes, defaults::kCaptureMemoryMiB << 20);
    SessionOptions given;
    given.frames = 0;  // a user's 0 is kept, so that prepareSession can refuse it
    given.pngLevel = 0;
    EXPECT_EQ(*withDefaults(given).frames, 0);
    EXPECT_EQ(*withDefaults(given).pngLevel, 0);
}

TEST(SessionOptions, ImpossibleValuesAreUsageErrorsBeforeAnyWork) {
    auto refused = [](SessionOptions options, const std::string& mentions) {
        Result<SessionPlan> run = prepareSession(options);
        ASSERT_FALSE(run.ok()) << mentions;
        EXPECT_EQ(run.error().category(), Category::Usage) << run.error().text();
        EXPECT_NE(run.error().text().find(mentions), std::string::npos) << run.error().text();
    };
    SessionOptions o = probeOptions();
    o.encoderThreads = 100000;
    refused(o, "--encoder-threads");
    o = probeOptions();
    o.frames = 0;
    refused(o, "frames: must be at least 1");
    o = probeOptions();
    o.settings.fps = 0;
    refused(o, "fps: must be");
    o = probeOptions();
    o.settings.fps = std::numeric_limits<double>::quiet_NaN();
    refused(o, "fps: must be");
    o = probeOptions();
    o.settings.width = 0;
    refused(o, "size: canvas size 0x8");
    o = probeOptions();
    o.settings.frameTimeout = -1;
    refused(o, "frame_timeout: must be");
    o = probeOptions();
    o.settings.height.reset();
    refused(o, "size: give both width and height");
    o = probeOptions();
    o.settings.date = "2024-02-30";
    refused(o, "date: date \"2024-02-30\" is not");
    o = probeOptions();
    o.pngLevel = 10;
    refused(o, "--png-level");
    o = probeOptions();
    o.captureEvery = 0;
    refused(o, "--capture-every");
}

// The library names the setting, not a CLI flag: Diagnostic::field holds it, and the CLI shows its
// flag there instead (tools/toyhost/SessionFlags.h; tests/gl/test_cli_errors.cpp).
TEST(SessionOptions, ASettingsErrorNamesTheSettingInItsField) {
    SessionOptions o = probeOptions();
    o.settings.width = -1;
    o.settings.height = 10;
    Result<SessionPlan> run = prepareSession(o);
    ASSERT_FALSE(run.ok());
    EXPECT_EQ(run.error().first().field, "size");
    EXPECT_EQ(run.error().first().message.find("--"), std::string::npos) << run.error().text();
    EXPECT_EQ(formatDiagnostic(run.error().first()),
              "error: size: canvas size -1x10 is not between 1x1 and 16384x16384 [usage.size]");
}

TEST(SessionOptions, PrepareDecodesTheImagesAndReportsStandIns) {
    SessionOptions o;
    o.target = sourceDir() / "shadertoys/uniform-probe";
    Result<SessionPlan> run = prepareSession(o);
    ASSERT_TRUE(run.ok()) << run.error().text();
    EXPECT_EQ(*run->options.settings.width, defaults::kCanvasWidth);
    ASSERT_FALSE(run->shadertoy.images.standIns().empty());
    EXPECT_EQ(run->shadertoy.images.standIns().front().name, "RGBA Noise Small");
}

}  // namespace
}  // namespace toyhost::testing
