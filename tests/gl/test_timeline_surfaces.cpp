// One scripted run (mouse and key scripts, a start time, a date and a frame rate) through every
// headless surface: `toyhost run`, the C++ Session and compareShadertoys all step the same fixed-step
// input (timing/Timeline.h) and give byte-identical frames; Python's is python/tests/test_timeline.py.
#include "GlTestSupport.h"

#include <toyhost/Compare.h>
#include <toyhost/Session.h>

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 48, kHeight = 32, kFrames = 9;
constexpr const char* kDate = "2024-02-29T23:59:58";

struct ScriptedRun {
    fs::path dir = freshOutputDir("timeline-surfaces");
    fs::path mouse = dir / "mouse.json";
    fs::path keys = dir / "keys.json";
    fs::path probe = sourceDir() / "shadertoys/timeline-probe";
    ScriptedRun() {
        writeFile(mouse, R"([{"frame": 1, "type": "down", "x": 8, "y": 6},
                             {"frame": 2, "type": "move", "to": {"frame": 6, "x": 20, "y": 25}},
                             {"time": 1.7, "type": "up"}])");
        writeFile(keys, R"([{"frame": 3, "type": "down", "key": 65}, {"frame": 5, "type": "up", "key": 65},
                            {"time": 1.75, "type": "tap", "key": 65}])");
    }
    SessionSettings settings() const {
        SessionSettings s;
        s.width = kWidth;
        s.height = kHeight;
        s.fps = 24;
        s.startTime = 1.5;
        s.date = kDate;
        s.mouseScript = mouse;
        s.keyScript = keys;
        return s;
    }
    // The CLI's frames, rows top first as the library reads them.
    std::vector<std::vector<std::uint8_t>> cliFrames() const {
        const CommandResult cli =
            runToyhost("run " + probe.string() + " --headless --size 48x32 --frames " + std::to_string(kFrames) +
                       " --fps 24 --start-time 1.5 --date " + kDate + " --mouse-script " + mouse.string() +
                       " --key-script " + keys.string() + " --quiet --out " + (dir / "f_%d.png").string());
        EXPECT_EQ(cli.exitCode, 0) << cli.output;
        std::vector<std::vector<std::uint8_t>> frames;
        for (int n = 0; n < kFrames; ++n) {
            Result<Image8> png = readPng(dir / ("f_" + std::to_string(n) + ".png"));
            EXPECT_TRUE(png.ok()) << (png ? "" : png.error().text());
            if (!png) return frames;
            // Image8 is bottom row first: flip to top first.
            std::vector<std::uint8_t> top(png->rgba.size());
            const std::size_t row = static_cast<std::size_t>(kWidth) * 4;
            for (int y = 0; y < kHeight; ++y)
                std::copy_n(png->rgba.begin() + static_cast<std::ptrdiff_t>((kHeight - 1 - y) * row), row,
                            top.begin() + static_cast<std::ptrdiff_t>(y * row));
            frames.push_back(std::move(top));
        }
        return frames;
    }
};

TEST(TimelineSurfaces, RunSessionAndCompareGiveTheSameScriptedFrames) {
    const ScriptedRun run;
    const auto cli = run.cliFrames();
    ASSERT_EQ(cli.size(), static_cast<std::size_t>(kFrames));
    // The run is not trivial: the scripts change the picture (the frames differ from each other).
    EXPECT_NE(cli[2], cli[6]);

    Result<Shadertoy> probe = Shadertoy::load(run.probe);
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe, run.settings());
        ASSERT_TRUE(session.ok()) << session.error().text();
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(kWidth) * kHeight * 4);
        for (int n = 0; n < kFrames; ++n) {
            EXPECT_DOUBLE_EQ((*session)->timeOf(n), 1.5 + n / 24.0);
            ASSERT_TRUE((*session)->step().ok());
            ASSERT_TRUE((*session)->read("Image", pixels).ok());
            EXPECT_EQ(pixels, cli[static_cast<std::size_t>(n)]) << "C++ Session, frame " << n;
        }
    });

    CompareSettings compare;
    compare.session = run.settings();  // the scripts in it reach both sessions
    compare.frames = kFrames;
    int compared = 0;
    compare.onFrame = [&](const ComparedFrame& frame) {
        const std::size_t n = static_cast<std::size_t>(frame.difference.frame);
        EXPECT_TRUE(std::equal(frame.a.begin(), frame.a.end(), cli[n].begin(), cli[n].end())) << "compare, frame " << n;
        EXPECT_DOUBLE_EQ(frame.difference.time, 1.5 + static_cast<double>(n) / 24.0);
        ++compared;
        return true;
    };
    runOnGlThread([&] {
        Result<CompareReport> report = compareShadertoys(*probe, *probe, compare);
        ASSERT_TRUE(report.ok()) << report.error().text();
        EXPECT_TRUE(report->equal());
    });
    EXPECT_EQ(compared, kFrames);
}

TEST(TimelineSurfaces, ADifferentScriptGivesOtherFrames) {
    // The comparison above can fail: without the key script the same run is another picture.
    const ScriptedRun run;
    const auto cli = run.cliFrames();
    ASSERT_EQ(cli.size(), static_cast<std::size_t>(kFrames));
    Result<Shadertoy> probe = Shadertoy::load(run.probe);
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    SessionSettings settings = run.settings();
    settings.keyScript.reset();
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe, settings);
        ASSERT_TRUE(session.ok()) << session.error().text();
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(kWidth) * kHeight * 4);
        for (int n = 0; n < 4; ++n) ASSERT_TRUE((*session)->step().ok());
        ASSERT_TRUE((*session)->read("Image", pixels).ok());
        EXPECT_NE(pixels, cli[3]) << "frame 3 with the key held differs from frame 3 without";
    });
}

}  // namespace
}  // namespace toyhost::testing
