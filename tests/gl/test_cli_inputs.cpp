// Scripted mouse and keys reach the shader through the CLI (--mouse, --mouse-script,
// --key-script), read back from uniform-probe's Buffer A (pixel 2 = iMouse, pixel 9 = keyboard
// rows of key 'A').
#include "GlTestSupport.h"

#include <chrono>
#include <fstream>
#include <iterator>

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::array<float, 4> pixel(const ImageF32& image, int x) {
    const size_t i = static_cast<size_t>(x) * 4;  // bottom row first: row 0 is y = 0
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}

std::string bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class CliInputs : public ::testing::Test {
protected:
    ImageF32 frame(const fs::path& dir, int n) {
        auto exr = readExr(dir / ("a_" + std::to_string(n) + ".exr"));
        EXPECT_TRUE(exr.ok()) << exr.error().text();
        return exr.ok() ? *exr : ImageF32{};
    }
    std::string probe() const { return "run '" + (sourceDir() / "shadertoys/uniform-probe").string() + "' --size 64x8 --quiet "; }
};

TEST_F(CliInputs, MouseHeldFromFrameZero) {
    const fs::path dir = freshOutputDir("cli-inputs/mouse");
    auto run = runToyhost(probe() + "--frames 2 --mouse 12,5 --capture-pass A --out '" + (dir / "a_%d.exr").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(pixel(frame(dir, 0), 2), (std::array<float, 4>{12, 5, 12, 5}));
    EXPECT_EQ(pixel(frame(dir, 1), 2), (std::array<float, 4>{12, 5, 12, -5}));
}

TEST_F(CliInputs, MouseAndKeyScriptsReplayDragsAndPresses) {
    const fs::path dir = freshOutputDir("cli-inputs/scripts");
    std::ofstream(dir / "mouse.json") << R"([{"frame": 1, "type": "down", "x": 10, "y": 4},
        {"frame": 2, "type": "move", "x": 20, "y": 6}, {"frame": 3, "type": "up"}])";
    std::ofstream(dir / "keys.json") << R"([{"frame": 1, "type": "down", "key": "A"}, {"frame": 3, "type": "up", "key": 65}])";
    auto run = runToyhost(probe() + "--frames 4 --mouse-script '" + (dir / "mouse.json").string() + "' --key-script '" +
                          (dir / "keys.json").string() + "' --capture-pass A --out '" + (dir / "a_%d.exr").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(pixel(frame(dir, 0), 2), (std::array<float, 4>{0, 0, 0, 0}));
    EXPECT_EQ(pixel(frame(dir, 1), 2), (std::array<float, 4>{10, 4, 10, 4}));
    EXPECT_EQ(pixel(frame(dir, 2), 2), (std::array<float, 4>{20, 6, 10, -4}));
    EXPECT_EQ(pixel(frame(dir, 3), 2), (std::array<float, 4>{20, 6, -10, -4}));
    EXPECT_EQ(pixel(frame(dir, 0), 9), (std::array<float, 4>{44100, 0, 0, 0}));
    EXPECT_EQ(pixel(frame(dir, 1), 9), (std::array<float, 4>{44100, 1, 1, 1}));
    EXPECT_EQ(pixel(frame(dir, 2), 9), (std::array<float, 4>{44100, 1, 0, 1}));
    EXPECT_EQ(pixel(frame(dir, 3), 9), (std::array<float, 4>{44100, 0, 0, 1}));
}

TEST_F(CliInputs, BadScriptNamesFileEventAndField) {
    const fs::path dir = freshOutputDir("cli-inputs/bad");
    std::ofstream(dir / "mouse.json") << R"([{"frame": 0, "type": "down", "x": 1}])";
    auto run = runToyhost(probe() + "--mouse-script '" + (dir / "mouse.json").string() + "'");
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find((dir / "mouse.json").string() + ": error: event 0: \"y\" is missing"), std::string::npos) << run.output;
}

TEST_F(CliInputs, CaptureEveryKeepsMultiplesAndTheLastFrame) {
    const fs::path dir = freshOutputDir("cli-inputs/every");
    auto run = runToyhost(probe() + "--frames 8 --capture-every 3 --out '" + (dir / "f_%d.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"f_0.png", "f_3.png", "f_6.png", "f_7.png"}));
}

TEST_F(CliInputs, FixedTimeStepGivesITimeAndIFrame) {
    const fs::path dir = freshOutputDir("cli-inputs/time");
    auto run = runToyhost(probe() + "--frames 3 --fps 30 --start-time 1.5 --date 2024-02-29T23:59:59 --capture-pass A --out '" +
                          (dir / "a_%d.exr").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto t = pixel(frame(dir, 2), 1);
    EXPECT_FLOAT_EQ(t[0], 1.5f + 2.0f / 30.0f);
    EXPECT_FLOAT_EQ(t[1], 1.0f / 30.0f);
    EXPECT_FLOAT_EQ(t[2], 30.0f);
    EXPECT_EQ(t[3], 2.0f);
    // iDate: frame 2 is 2/30 s after 23:59:59 on 29 February 2024 (month index 1).
    auto d = pixel(frame(dir, 2), 3);
    EXPECT_EQ(d[0], 2024.0f);
    EXPECT_EQ(d[1], 1.0f);
    EXPECT_EQ(d[2], 29.0f);
    EXPECT_NEAR(d[3], 86399.0f + 2.0f / 30.0f, 0.01f);
}

// --paced: a headless run draws --fps frames per second of wall time (a live stream's rate) and the
// same frames as an unpaced run. Only a lower bound on the time: a loaded machine is slower, never
// faster. A stop is not held up by the wait for the next frame (20 s away here).
TEST_F(CliInputs, PacedHeadlessRunKeepsTheRateAndTheFrames) {
    const fs::path dir = freshOutputDir("cli-inputs/paced");
    const auto from = std::chrono::steady_clock::now();
    auto paced = runToyhost(probe() + "--frames 6 --fps 10 --paced --out '" + (dir / "p_%d.png").string() + "'");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
    ASSERT_EQ(paced.exitCode, 0) << paced.output;
    EXPECT_GE(seconds, 5 / 10.0) << "6 frames at --fps 10 --paced took " << seconds << " s";
    auto unpaced = runToyhost(probe() + "--frames 6 --fps 10 --out '" + (dir / "u_%d.png").string() + "'");
    ASSERT_EQ(unpaced.exitCode, 0) << unpaced.output;
    for (int n = 0; n < 6; ++n)
        EXPECT_EQ(bytesOf(dir / ("p_" + std::to_string(n) + ".png")), bytesOf(dir / ("u_" + std::to_string(n) + ".png")))
            << "frame " << n;

    const auto stopFrom = std::chrono::steady_clock::now();
    auto stopped = runCommand("timeout", "-s TERM 2 '" + toyhostBinary().string() + "' " + probe() + "--frames 5 --fps 0.05 --paced");
    const double stopSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - stopFrom).count();
    EXPECT_EQ(stopped.exitCode, 124) << stopped.output;  // timeout's code: the signal was sent
    EXPECT_LT(stopSeconds, 15.0) << "SIGTERM waited for the next paced frame";

    auto window = runToyhost(probe() + "--window --paced --fps 10");
    EXPECT_EQ(window.exitCode, 2) << window.output;
    EXPECT_NE(window.output.find("--paced is for headless runs"), std::string::npos) << window.output;
}

}  // namespace
}  // namespace toyhost::testing
