// Long unattended runs, through the CLI as a farm or a user runs them: checkpoints that resume
// byte-identically (Mountains & Lakes: its water total and its pixels), render-farm shards whose
// union is the single run (GNU parallel, 4 shards), signals that stop a run stuck in a long draw
// within the grace period (signals at random moments of every kind of run are in
// test_adversarial.cpp).
#include "GlTestSupport.h"

#include <chrono>
#include <fstream>
#include <optional>
#include <random>
#include <thread>

#include "Processes.h"
#include "image/ImageFile.h"
#include "image/ImageWriters.h"
#include "session/Checkpoint.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}


// Every entry of `dir` (hidden ones included), by name.
std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// The summed water depth (.y) over Mountains & Lakes' 256x256 simulation grid.
double waterTotal(const ImageF32& bufferC) {
    double sum = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) sum += bufferC.rgba[(static_cast<std::size_t>(y) * bufferC.width + x) * 4 + 1];
    return sum;
}

// ---- checkpoints ------------------------------------------------------------------------------

class Checkpoints : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::exists(sharedDir() / "shadertoys/7tSSDD/bufferC.glsl")) GTEST_SKIP() << "needs ../shared/shadertoys/7tSSDD";
        dir_ = freshOutputDir(std::string("reliability/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    // Mountains & Lakes at the size of its 256x256 grid, 48 frames; extra options appended.
    CommandResult run(const std::string& options) {
        return runToyhost("run " + quoted(sourceDir() / "shadertoys/mountains-lakes") +
                          " --size 320x256 --frames 48 --quiet " + options);
    }
    fs::path dir_;
};

TEST_F(Checkpoints, ResumedFramesAreByteIdenticalAndTheWaterIsConserved) {
    // The uninterrupted run: Buffer C (the water) as raw floats and the picture, frames 40 and 47.
    ASSERT_EQ(run("--capture-every 40 --capture-pass C --out " + quoted(dir_ / "full/c_%04d.exr")).exitCode, 0);
    ASSERT_EQ(run("--capture-every 40 --out " + quoted(dir_ / "full/i_%04d.png")).exitCode, 0);
    // Stopped at frame 25 with a checkpoint (written at the end of a run), then resumed.
    auto first = runToyhost("run " + quoted(sourceDir() / "shadertoys/mountains-lakes") +
                            " --size 320x256 --frames 25 --quiet --checkpoint " + quoted(dir_ / "state.ckpt"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    auto resumed = run("--resume " + quoted(dir_ / "state.ckpt") + " --capture-every 40 --capture-pass C --out " +
                       quoted(dir_ / "resumed/c_%04d.exr"));
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    ASSERT_EQ(run("--resume " + quoted(dir_ / "state.ckpt") + " --capture-every 40 --out " +
                  quoted(dir_ / "resumed/i_%04d.png"))
                  .exitCode,
              0);
    // A resumed run renders from the checkpoint's frame: nothing before it is written.
    EXPECT_EQ(entries(dir_ / "resumed"),
              (std::vector<std::string>{"c_0040.exr", "c_0047.exr", "i_0040.png", "i_0047.png"}));
    for (const char* file : {"c_0040.exr", "c_0047.exr", "i_0040.png", "i_0047.png"})
        EXPECT_EQ(bytesOf(dir_ / "resumed" / file), bytesOf(dir_ / "full" / file)) << file << " differs after resume";
    auto water = readExr(dir_ / "resumed/c_0047.exr");
    ASSERT_TRUE(water.ok()) << water.error().text();
    const double expected = 256.0 * 256.0 * 0.05;
    EXPECT_LT(std::abs(waterTotal(*water) - expected) / expected, 1e-4) << "water total " << waterTotal(*water);
}

TEST_F(Checkpoints, CheckpointEveryKAndOnSigtermThenResumeGivesTheSameFrame) {
    // A run that writes a checkpoint every 8 frames and is stopped by SIGTERM part-way: the
    // checkpoint holds the state after the last frame it finished, wherever that was.
    BackgroundProcess killed(toyhostBinary(),
                             {"run", (sourceDir() / "shadertoys/mountains-lakes").string(), "--headless", "--size",
                              "320x256", "--frames", "100000", "--quiet", "--checkpoint",
                              (dir_ / "state.ckpt").string(), "--checkpoint-every", "8"},
                             dir_ / "killed.log");
    // The signal comes once a checkpoint past frame 47 exists: the case this test once skipped
    // ("the run passed frame 47 before SIGTERM") is the one it always covers now.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int written = 0;
    while (written < 48 && std::chrono::steady_clock::now() < deadline) {
        if (fs::exists(dir_ / "state.ckpt"))
            if (Result<Checkpoint> seen = readCheckpoint(dir_ / "state.ckpt"); seen.ok()) written = seen->state.frame;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_GE(written, 48) << killed.log();
    killed.signal(SIGTERM);
    EXPECT_EQ(killed.wait(20), 143) << killed.log();
    EXPECT_EQ(entries(dir_), (std::vector<std::string>{"killed.log", "state.ckpt"})) << "no partial files";
    // However far the run got before the signal, the resumed run goes 8 frames past the
    // checkpoint and its last frame equals that of one uninterrupted run.
    Result<Checkpoint> checkpoint = readCheckpoint(dir_ / "state.ckpt");
    ASSERT_TRUE(checkpoint.ok()) << checkpoint.error().text();
    const int stoppedAt = checkpoint->state.frame;
    ASSERT_GE(stoppedAt, 48);
    const int frames = stoppedAt + 8;
    char last[32];
    std::snprintf(last, sizeof last, "i_%04d.png", frames - 1);
    auto runTo = [&](const std::string& options) {
        return runToyhost("run " + quoted(sourceDir() / "shadertoys/mountains-lakes") + " --headless --size 320x256 --frames " +
                          std::to_string(frames) + " --quiet --capture-every 100000 " + options);
    };
    auto resumed = runTo("--resume " + quoted(dir_ / "state.ckpt") + " --out " + quoted(dir_ / "resumed/i_%04d.png"));
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    ASSERT_EQ(runTo("--out " + quoted(dir_ / "full/i_%04d.png")).exitCode, 0);
    EXPECT_EQ(entries(dir_ / "resumed"), std::vector<std::string>{last}) << "frames " << stoppedAt << " .. " << frames - 1;
    EXPECT_EQ(bytesOf(dir_ / "resumed" / last), bytesOf(dir_ / "full" / last)) << last << " after resuming at " << stoppedAt;
}

TEST_F(Checkpoints, ResumeRefusesAnotherShadertoyOrAnotherClock) {
    ASSERT_EQ(runToyhost("run " + quoted(sourceDir() / "shadertoys/mountains-lakes") +
                         " --size 320x256 --frames 4 --quiet --checkpoint " + quoted(dir_ / "state.ckpt"))
                  .exitCode,
              0);
    auto other = runToyhost("run " + quoted(sourceDir() / "shadertoys/ripple-pool") + " --frames 8 --resume " +
                            quoted(dir_ / "state.ckpt"));
    EXPECT_EQ(other.exitCode, 1) << other.output;
    EXPECT_NE(other.output.find("the checkpoint was made from other code"), std::string::npos) << other.output;
    auto clock = run("--fps 30 --resume " + quoted(dir_ / "state.ckpt"));
    EXPECT_EQ(clock.exitCode, 2) << clock.output;
    EXPECT_NE(clock.output.find("the checkpoint was made with --fps 60"), std::string::npos) << clock.output;
    writeFile(dir_ / "bad.ckpt", "TOYHOST-CHECKPOINT 1\n{\"shadertoy\": 1}\n");
    auto bad = run("--resume " + quoted(dir_ / "bad.ckpt"));
    EXPECT_EQ(bad.exitCode, 1) << bad.output;
    EXPECT_NE(bad.output.find((dir_ / "bad.ckpt").string() + ": error: not a usable checkpoint"), std::string::npos)
        << bad.output;
    // Truncated: the header promises more floats than the file holds.
    const std::string whole = bytesOf(dir_ / "state.ckpt");
    writeFile(dir_ / "short.ckpt", whole.substr(0, whole.size() - 100));
    auto truncated = run("--resume " + quoted(dir_ / "short.ckpt"));
    EXPECT_EQ(truncated.exitCode, 1) << truncated.output;
    EXPECT_NE(truncated.output.find("truncated"), std::string::npos) << truncated.output;
}

// ---- render-farm shards -----------------------------------------------------------------------

// Four shards run by GNU parallel (as docs/farm.md shows), compared file by file with one run.
TEST(Shards, FourParallelShardsEqualTheSingleRunByteForByte) {
    if (shell("command -v parallel").first != 0) GTEST_FAIL() << "GNU parallel is not installed (scripts/install-deps.sh installs it)";
    const fs::path dir = freshOutputDir("reliability/shards");
    const fs::path pool = sourceDir() / "shadertoys/ripple-pool";
    const fs::path ocean = sourceDir() / "shadertoys/exp-sine-ocean";
    struct Case {
        const char* name;
        fs::path shadertoy;
    };
    // ripple-pool has a simulation buffer (earlier frames are simulated); exp-sine-ocean has none
    // (a shard starts at its first frame).
    for (const Case& c : {Case{"pool", pool}, Case{"ocean", ocean}}) {
        SCOPED_TRACE(c.name);
        const std::string common = " --size 96x54 --frames 40 --quiet --mouse-script " + quoted(pool / "drag.json");
        auto single = runToyhost("run " + quoted(c.shadertoy) + common + " --out " +
                                 quoted(dir / c.name / "single/f_%04d.png"));
        ASSERT_EQ(single.exitCode, 0) << single.output;
        auto shards = shell("parallel --will-cite --halt now,fail=1 -j 2 " + quoted(toyhostBinary()) + " run " +
                            quoted(c.shadertoy) + common + " --headless --shard {}/4 --out " +
                            quoted(dir / c.name / "shards/f_%04d.png") + " ::: 0 1 2 3 2>&1");
        ASSERT_EQ(shards.first, 0) << shards.second;
        const std::vector<std::string> files = entries(dir / c.name / "single");
        ASSERT_EQ(files.size(), 40u);
        EXPECT_EQ(entries(dir / c.name / "shards"), files);
        for (const std::string& file : files)
            EXPECT_EQ(bytesOf(dir / c.name / "shards" / file), bytesOf(dir / c.name / "single" / file)) << file;
    }
}

TEST(Shards, FrameRangeCapturesOnlyItsFrames) {
    const fs::path dir = freshOutputDir("reliability/frame-range");
    auto run = runToyhost("run " + quoted(sourceDir() / "shadertoys/ripple-pool") +
                          " --size 32x18 --frames 20 --frame-range 12:15 --quiet --out " + quoted(dir / "f_%04d.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(entries(dir), (std::vector<std::string>{"f_0012.png", "f_0013.png", "f_0014.png"}));
}

// ---- signals ------------------------------------------------------------------------------------

// A pass whose single frame takes far longer than the test (llvmpipe caps each loop near 65535
// iterations, so the work is in the loop body); with `fromFrame` 1, frame 0 is quick, so a
// checkpoint written after it marks the moment frame 1's endless draw begins.
void writeHeavyShadertoy(const fs::path& dir, int fromFrame = 0) {
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    std::string body;
    for (int k = 1; k <= 20; ++k) body += "        s += sin(x * " + std::to_string(k) + ".0 + s);\n";
    writeFile(dir / "image.glsl", "void mainImage(out vec4 c, in vec2 f) {\n    float s = 0.0;\n"
                                  "    int n = iFrame >= " + std::to_string(fromFrame) + " ? int(iResolution.x) * 200 : 0;\n"
                                  "    for (int i = 0; i < n; i++) {\n"
                                  "        float x = float(i) * f.x;\n" + body + "    }\n    c = vec4(s);\n}\n");
}

// Starts the heavy shadertoy writing `out`, and returns once frame 0 is done (its checkpoint is
// there): frame 1 is drawing, for longer than any test.
void startLongDraw(std::optional<BackgroundProcess>& run, const fs::path& dir, const fs::path& out, const std::string& log) {
    fs::remove(dir / "state.ckpt");
    run.emplace(toyhostBinary(),
                std::vector<std::string>{"run", (dir / "heavy").string(), "--headless", "--size", "320x180", "--frames", "3",
                                         "--frame-timeout", "0", "--checkpoint", (dir / "state.ckpt").string(),
                                         "--checkpoint-every", "1", "--out", out.string()},
                dir / log);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(dir / "state.ckpt") && std::chrono::steady_clock::now() < deadline && run->running())
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_TRUE(fs::exists(dir / "state.ckpt")) << run->log();
}

TEST(Signals, SigintDuringALongDrawIsAcknowledgedAndEndsWithinTheGracePeriod) {
    const fs::path dir = freshOutputDir("reliability/long-draw");
    writeHeavyShadertoy(dir / "heavy", 1);
    for (const char* out : {"f_%d.png", "movie.mp4"}) {
        SCOPED_TRACE(out);
        fs::remove_all(dir / "out");
        std::optional<BackgroundProcess> run;
        startLongDraw(run, dir, dir / "out" / out, "run.log");
        const auto signalled = std::chrono::steady_clock::now();
        run->signal(SIGINT);
        EXPECT_TRUE(run->waitForLog("SIGINT: stopping before the next frame", 1.0)) << run->log();
        EXPECT_EQ(run->wait(10), 130) << run->log();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count();
        EXPECT_LT(seconds, 6.0) << "the run did not end within the grace period";
        // Frame 0's image is complete and stays; the video being encoded is discarded; nothing
        // unfinished is left.
        const std::vector<std::string> left = entries(dir / "out");
        if (std::string(out) == "movie.mp4") EXPECT_TRUE(left.empty()) << "left behind: " << left.size() << " entries";
        else EXPECT_EQ(left, (std::vector<std::string>{"f_0.png"}));
    }
    // A second signal ends it at once.
    std::optional<BackgroundProcess> run;
    startLongDraw(run, dir, dir / "out2" / "movie.mp4", "run2.log");
    run->signal(SIGTERM);
    ASSERT_TRUE(run->waitForLog("SIGTERM: stopping", 1.0)) << run->log();
    const auto second = std::chrono::steady_clock::now();
    run->signal(SIGTERM);
    EXPECT_EQ(run->wait(10), 143) << run->log();
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - second).count(), 2.0);
    EXPECT_TRUE(entries(dir / "out2").empty()) << "a second signal left files";
    EXPECT_EQ(shell("pgrep -a ffmpeg").second.find((dir / "out2").string()), std::string::npos)
        << "an ffmpeg was left running";
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// ---- the watchdog ---------------------------------------------------------------------------

TEST(Watchdog, AFrameOverItsLimitEndsTheRunNamingThePass) {
    const fs::path dir = freshOutputDir("reliability/watchdog-frame");
    writeHeavyShadertoy(dir / "heavy");
    const auto started = std::chrono::steady_clock::now();
    auto run = runToyhost("run " + quoted(dir / "heavy") + " --size 320x180 --frames 3 --frame-timeout 1 --out " +
                          quoted(dir / "out/f_%d.png"));
    EXPECT_EQ(run.exitCode, 124) << run.output;
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(), 8.0);
    EXPECT_NE(run.output.find("error: Image: frame 0 has been drawing this pass for"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("[watchdog.frame]"), std::string::npos) << run.output;
    EXPECT_TRUE(entries(dir / "out").empty());
}

TEST(Watchdog, ACompilationOverItsLimitEndsTheRun) {
    // 40000 globals keep Mesa's GLSL front end busy for longer than the 0.2 s allowed.
    const fs::path dir = freshOutputDir("reliability/watchdog-compile");
    std::string code;
    for (int i = 0; i < 40000; ++i) code += "float g" + std::to_string(i) + " = " + std::to_string(i) + ".0;\n";
    code += "void mainImage(out vec4 c, in vec2 f) { c = vec4(g1 + g39999); }\n";
    writeFile(dir / "big/image.glsl", code);
    writeFile(dir / "big/manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    auto run = runToyhost("run " + quoted(dir / "big") + " --size 8x8 --compile-timeout 0.2 --out " +
                          quoted(dir / "out/f.png"));
    EXPECT_EQ(run.exitCode, 124) << run.output;
    EXPECT_NE(run.output.find("error: Image: compiling has taken"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("[watchdog.compile]"), std::string::npos) << run.output;
    EXPECT_TRUE(entries(dir / "out").empty());
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// A texture beyond toyhost's 16384 a side is refused before GL, naming the file and the channel.
TEST(TextureLimits, AnImageTooLargeIsNamedWithItsChannel) {
    const fs::path dir = freshOutputDir("reliability/texture-too-large");
    const int width = 16390, height = 2;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4, 128);
    ASSERT_TRUE(writePng(dir / "toy/wide.png", width, height, pixels).ok());
    writeFile(dir / "toy/manifest.json",
              R"({"passes": {"Image": {"source": "i.glsl", "channels": {"iChannel1": {"texture": "wide.png"}}}}})");
    writeFile(dir / "toy/i.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel1, f); }\n");
    auto run = runToyhost("run " + quoted(dir / "toy") + " --size 8x8 --out " + quoted(dir / "out/f.png"));
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find((dir / "toy/wide.png").string() + ": error: Image / iChannel1: the image is 16390x2, "
                                                                   "larger than the 16384"),
              std::string::npos)
        << run.output;
    EXPECT_TRUE(entries(dir / "out").empty());
}

}  // namespace
}  // namespace toyhost::testing
