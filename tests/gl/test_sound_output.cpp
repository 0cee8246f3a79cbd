// The Sound pass from rendering to the file: `toyhost sound --out` for every kind of output name (a
// name without an extension is a usage error found before rendering, `-` is WAV on stdout, a full
// device says so, a failing encoder leaves nothing), the renderer publishing each block for a
// watchdog and stopping between blocks when asked, and a runaway mainSound ended by the watchdog
// of `toyhost run`. (`toyhost sound` aborted with std::out_of_range, exit 134, for the first three.)
#include "GlTestSupport.h"

#include <atomic>
#include <thread>

#include "core/ChildProcess.h"
#include "render/SoundRenderer.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

const char* kImage = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
const char* kSine = "vec2 mainSound(int samp, float time) { return vec2(0.5 * sin(6.2831853 * 440.0 * time)); }\n";
// Minutes per 512x512 block on llvmpipe.
const char* kEndless = R"(vec2 mainSound(int samp, float time) {
    float s = 0.0;
    for (int j = 0; j < 100000; j++) for (int i = 0; i < 100000; i++) s += sin(time * float(i + j) + s);
    return vec2(s);
}
)";

fs::path soundShadertoy(const std::string& name, const std::string& sound) {
    const fs::path dir = freshOutputDir("sound_output/" + name);
    writeFile(dir / "image.glsl", kImage);
    writeFile(dir / "sound.glsl", sound);
    writeFile(dir / "manifest.json",
              R"({"passes": {"Image": {"source": "image.glsl"}, "Sound": {"source": "sound.glsl"}}})");
    return dir;
}

// Files in `dir` other than the shadertoy's own.
std::vector<std::string> leftovers(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name != "image.glsl" && name != "sound.glsl" && name != "manifest.json" && name != "bin") names.push_back(name);
    }
    return names;
}

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

TEST(SoundOutput, ANameWithoutAnExtensionIsAUsageErrorFoundBeforeRendering) {
    // The endless mainSound would run for hours: the name is checked first.
    const fs::path dir = soundShadertoy("no_extension", kEndless);
    auto run = runToyhost("sound '" + dir.string() + "' --out '" + (dir / "s").string() + "'");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find((dir / "s").string() + ": error: the audio format is chosen by the extension and this "
                              "name has no extension: give a name ending in .wav, .flac, .ogg, .opus, .mp3 or .m4a, or "
                              "- for WAV on stdout [usage.out]"),
              std::string::npos)
        << run.output;
    EXPECT_TRUE(leftovers(dir).empty());
    run = runToyhost("sound '" + dir.string() + "' --out '" + (dir / "s.aiff").string() + "'");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("this name ends in .aiff"), std::string::npos) << run.output;
}

TEST(SoundOutput, DashWritesAWavToStdout) {
    const fs::path dir = soundShadertoy("stdout", kSine);
    const std::string command = "'" + toyhostBinary().string() + "' sound '" + dir.string() + "' --seconds 1 --out - 2>'" +
                                (dir / "stderr.txt").string() + "' > '" + (dir / "stdout.wav").string() + "'";
    ::unsetenv("DISPLAY");
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::ifstream in(dir / "stdout.wav", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_EQ(bytes.size(), 44u + 44100u * 4u);
    EXPECT_EQ(bytes.compare(0, 4, "RIFF"), 0);
    EXPECT_EQ(bytes.compare(8, 4, "WAVE"), 0);
    std::ifstream err(dir / "stderr.txt");
    const std::string said((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
    EXPECT_NE(said.find("wrote WAV to stdout"), std::string::npos) << said;
}

TEST(SoundOutput, AFullDeviceSaysNoSpaceLeftOnDevice) {
    const fs::path dir = soundShadertoy("full", kSine);
    auto run = runToyhost("sound '" + dir.string() + "' --seconds 1 --out /dev/full");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(lower(run.output).find("/dev/full: error: write failed: no space left on device [io.no-space]"),
              std::string::npos)
        << run.output;
}

TEST(SoundOutput, AFailingEncoderLeavesNoFile) {
    if (!findExecutable("ffmpeg")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    const fs::path dir = soundShadertoy("failing_encoder", kSine);
    // An ffmpeg that writes half a file where it is told to, then fails.
    writeFile(dir / "bin" / "ffmpeg", "#!/bin/sh\nfor a; do out=$a; done\necho half > \"${out#file:}\"\n"
                                      "echo 'No space left on device' >&2\nexit 1\n");
    fs::permissions(dir / "bin" / "ffmpeg", fs::perms::owner_all);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", ((dir / "bin").string() + ":" + path).c_str(), 1);
    auto run = runToyhost("sound '" + dir.string() + "' --seconds 1 --out '" + (dir / "a.flac").string() + "'");
    ::setenv("PATH", path.c_str(), 1);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("ffmpeg could not write .flac audio: No space left on device [io.no-space]"),
              std::string::npos)
        << run.output;
    EXPECT_TRUE(leftovers(dir).empty()) << leftovers(dir).front();
}

TEST(SoundOutput, ARunawayMainSoundIsEndedByTheWatchdogOfARun) {
    // `toyhost run --out movie.mp4` renders the sound track first; a mainSound that never ends is
    // named by the watchdog like any pass (it used to run unwatched for ever).
    const fs::path dir = soundShadertoy("runaway", kEndless);
    auto run = runToyhost("run '" + dir.string() + "' --size 32x18 --frames 2 --frame-timeout 2 --quiet --out '" +
                          (dir / "movie.mp4").string() + "'");
    EXPECT_EQ(run.exitCode, 124) << run.output;
    EXPECT_NE(run.output.find("error: Sound: frame 0 has been drawing this pass for"), std::string::npos) << run.output;
    EXPECT_TRUE(leftovers(dir).empty());
}

class SoundRenderer : public GlTest {};

Result<PlayerPlan> soundPlan(const fs::path& dir) {
    Result<ManifestDesc> manifest = loadShadertoy(dir);
    if (!manifest) return manifest.error();
    return planPlayer(std::move(*manifest), MediaOptions{});
}

TEST_F(SoundRenderer, EachBlockIsPublishedAsDrawingTheSoundPass) {
    const fs::path dir = soundShadertoy("published", kSine);
    Result<PlayerPlan> plan = soundPlan(dir);
    ASSERT_TRUE(plan) << plan.error().text();
    RunActivity activity;
    SoundRenderDesc desc;
    desc.source = &*plan->soundSource;
    desc.seconds = 20;  // 4 blocks of 262144 samples
    const AttachedActivity attached(*context_, activity);
    // A watchdog's view, sampled from another thread while the blocks draw.
    std::atomic<bool> done{false};
    std::atomic<int> drawingSound{0}, maxBlock{-1};
    std::thread watchdog([&] {
        while (!done) {
            const RunActivity::Snapshot now = activity.snapshot();
            if (now.phase == RunActivity::Phase::Drawing && std::string(now.pass) == "Sound") {
                ++drawingSound;
                maxBlock = std::max(maxBlock.load(), now.frame);
            }
            std::this_thread::yield();
        }
    });
    Result<std::vector<float>> stereo = renderSound(*context_, plan->manifest, plan->images, desc);
    done = true;
    watchdog.join();
    ASSERT_TRUE(stereo) << stereo.error().text();
    EXPECT_EQ(stereo->size(), 2u * 20u * 44100u);
    EXPECT_GT(drawingSound.load(), 0) << "no block was seen drawing";
    EXPECT_LE(maxBlock.load(), 3);
    EXPECT_EQ(activity.snapshot().phase, RunActivity::Phase::Idle);
}

TEST_F(SoundRenderer, AStopRequestEndsItBetweenBlocksAsInterrupted) {
    const fs::path dir = soundShadertoy("stopped", kSine);
    Result<PlayerPlan> plan = soundPlan(dir);
    ASSERT_TRUE(plan) << plan.error().text();
    int asked = 0;
    SoundRenderDesc desc;  // 180 s: 31 blocks
    desc.source = &*plan->soundSource;
    desc.stopRequested = [&] { return ++asked == 3; };
    Result<std::vector<float>> stereo = renderSound(*context_, plan->manifest, plan->images, desc);
    ASSERT_FALSE(stereo);
    EXPECT_EQ(stereo.error().first().code, Code::Interrupted);
    EXPECT_EQ(stereo.error().category(), Category::Interrupted);
    EXPECT_EQ(asked, 3);  // two blocks drawn, then stopped before the third
}

TEST_F(SoundRenderer, AChannelTheSoundPassCannotReadIsNamed) {
    const fs::path dir = soundShadertoy("webcam", kSine);
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"},
        "Sound": {"source": "sound.glsl", "channels": {"iChannel1": {"webcam": true}}}}})");
    Result<PlayerPlan> plan = soundPlan(dir);
    ASSERT_TRUE(plan) << plan.error().text();
    SoundRenderDesc desc;
    desc.source = &*plan->soundSource;
    Result<std::vector<float>> stereo = renderSound(*context_, plan->manifest, plan->images, desc);
    ASSERT_FALSE(stereo);
    EXPECT_EQ(formatDiagnostic(stereo.error().first()),
              "error: Sound / iChannel1: the Sound pass is rendered before any frame, so it cannot read a webcam channel "
              "[sound.channel]");
}

}  // namespace
}  // namespace toyhost::testing
