// Video channels frame by frame: the frame a video channel shows at iFrame N is the file's frame
// floor(iTime * fps) computed from the exact frame time, for 10,000 frames (the float iTime showed
// the previous frame at 4,629 of 10,001 frames of a 30 fps clip at --fps 30); shards that start
// mid-clip show the same frames; and a frame the decoder has not decoded yet is waited for where
// a watchdog sees it (RunActivity::WaitingForInput).
//
// The clip encodes each frame's index in 16 blocks of 8x8 pixels, black or white (lavfi's geq), so
// a shader reads the index back exactly; the test reads one RGBA pixel per frame from `--out -`.
#include "GlTestSupport.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>

#include "core/ChildProcess.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// Frame n of the clip: bit b of n is block (b % 4, b / 4) (8x8 pixels, rows from the top), white
// for 1. 32x32 grey, lossless (FFV1).
fs::path makeIndexClip(const fs::path& dir, int frames, int fps) {
    const fs::path clip = dir / "index.mkv";
    const std::string command =
        "ffmpeg -v error -nostdin -y -f lavfi -i \"nullsrc=s=32x32:r=" + std::to_string(fps) +
        ",format=gray,geq=lum='255*mod(floor(N/pow(2\\,floor(X/8)+4*floor(Y/8)))\\,2)'\" -frames:v " +
        std::to_string(frames) + " -c:v ffv1 '" + clip.string() + "'";
    if (std::system(command.c_str()) != 0) return {};
    return clip;
}

// A 1x1 Image that reads the index back: R + 256 G, and B = 255 when every block was pure black or
// white (nothing blurred or blended).
const char* kIndexReader = R"(void mainImage(out vec4 c, in vec2 f) {
    float index = 0.0, clean = 1.0;
    for (int b = 0; b < 16; ++b) {
        vec2 block = vec2(float(b % 4), float(b / 4));
        float v = texture(iChannel0, vec2(block.x * 8.0 + 4.0, 32.0 - (block.y * 8.0 + 4.0)) / 32.0).r;
        if (v > 0.02 && v < 0.98) clean = 0.0;
        index += step(0.5, v) * exp2(float(b));
    }
    c = vec4(mod(index, 256.0), floor(index / 256.0), 0.0, 0.0) / 255.0 + vec4(0.0, 0.0, clean, 1.0);
}
)";

fs::path indexShadertoy(const std::string& name, int frames, int fps) {
    const fs::path dir = freshOutputDir("video_frames/" + name);
    writeFile(dir / "image.glsl", kIndexReader);
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl",
        "channels": {"iChannel0": {"video": "index.mkv", "filter": "nearest"}}}}})");
    if (makeIndexClip(dir, frames, fps).empty()) return {};
    return dir;
}

// Runs toyhost with `arguments` and returns its stdout (the raw frames); stderr goes to `log`.
std::string rawFrames(const std::string& arguments, const fs::path& log, int& exitCode) {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    const std::string command = "'" + toyhostBinary().string() + "' " + arguments + " 2>'" + log.string() + "'";
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return out;
    char chunk[65536];
    std::size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, pipe)) > 0) out.append(chunk, n);
    const int status = pclose(pipe);
    exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// Checks that captured frame i shows video frame expected(i), and that every frame read clean.
template <class Expected>
void expectFrames(const std::string& raw, int frames, Expected expected) {
    ASSERT_EQ(raw.size(), static_cast<std::size_t>(frames) * 4);
    int wrong = 0;
    for (int i = 0; i < frames; ++i) {
        const auto* p = reinterpret_cast<const std::uint8_t*>(raw.data()) + 4 * i;
        const int shown = p[0] + 256 * p[1];
        const int want = expected(i);
        if (shown != want || p[2] != 255) {
            if (++wrong <= 5)
                ADD_FAILURE() << "frame " << i << " shows video frame " << shown << ", expected " << want
                              << (p[2] != 255 ? " (blocks not clean)" : "");
        }
    }
    EXPECT_EQ(wrong, 0) << "frames showing the wrong video frame";
}

class VideoFrames : public GlTest {};

TEST_F(VideoFrames, AThirtyFpsClipAtFps30ShowsFrameNAtFrameNUpTo10000) {
    if (!findExecutable("ffmpeg")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    constexpr int kFrames = 10001;
    const fs::path dir = indexShadertoy("fps30", kFrames, 30);
    ASSERT_FALSE(dir.empty()) << "ffmpeg could not make the clip";
    int exit = -1;
    const std::string raw = rawFrames("run '" + dir.string() + "' --fps 30 --frames " + std::to_string(kFrames) +
                                          " --size 1x1 --quiet --out -",
                                      dir / "stderr.txt", exit);
    ASSERT_EQ(exit, 0) << readAll(dir / "stderr.txt");
    expectFrames(raw, kFrames, [](int n) { return n; });
}

TEST_F(VideoFrames, AShardStartingMidClipAndASlowerRunShowTheFilesFrames) {
    if (!findExecutable("ffmpeg")) GTEST_FAIL() << "needs ffmpeg (scripts/install-deps.sh installs it)";
    constexpr int kClip = 9000;  // 300 s at 30 fps
    const fs::path dir = indexShadertoy("shards", kClip, 30);
    ASSERT_FALSE(dir.empty()) << "ffmpeg could not make the clip";
    int exit = -1;
    // A shard from 250 s on (frame 7500), through the loop back to frame 0.
    std::string raw = rawFrames("run '" + dir.string() + "' --fps 30 --start-time 250 --frames 2000 --size 1x1 "
                                "--quiet --out -",
                                dir / "stderr.txt", exit);
    ASSERT_EQ(exit, 0) << readAll(dir / "stderr.txt");
    expectFrames(raw, 2000, [](int n) { return (7500 + n) % kClip; });
    // At --fps 60 every video frame shows twice; at --fps 12 the decoder skips 1.5 frames a frame.
    raw = rawFrames("run '" + dir.string() + "' --fps 60 --frames 3000 --size 1x1 --quiet --out -",
                    dir / "stderr.txt", exit);
    ASSERT_EQ(exit, 0) << readAll(dir / "stderr.txt");
    expectFrames(raw, 3000, [](int n) { return n / 2; });
    raw = rawFrames("run '" + dir.string() + "' --fps 12 --frames 2000 --size 1x1 --quiet --out -",
                    dir / "stderr.txt", exit);
    ASSERT_EQ(exit, 0) << readAll(dir / "stderr.txt");
    expectFrames(raw, 2000, [](int n) { return (n * 5) / 2; });
}

// A decoder that has not decoded the frame yet: the frame waits for it, and a watchdog on another
// thread sees the render thread waiting for the video (pass, iFrame) rather than idle. The decoder
// is a stand-in for ffmpeg that sends frame 0 and then nothing until it is killed.
TEST_F(VideoFrames, AFrameTheDecoderHasNotReachedIsWaitedForWhereAWatchdogSeesIt) {
    if (!findExecutable("ffmpeg") || !findExecutable("ffprobe")) GTEST_FAIL() << "needs ffmpeg and ffprobe (scripts/install-deps.sh installs them)";
    const fs::path dir = indexShadertoy("stalled", 60, 30);
    ASSERT_FALSE(dir.empty()) << "ffmpeg could not make the clip";
    const fs::path bin = dir / "bin";
    fs::create_directories(bin);
    // Frame 0 (32x32 RGBA), then the pid to kill (exec keeps it), then silence.
    writeFile(bin / "ffmpeg", "#!/bin/sh\nhead -c 4096 /dev/zero\necho $$ > '" + (dir / "stalled.pid").string() +
                                  "'\nexec sleep 600\n");
    fs::permissions(bin / "ffmpeg", fs::perms::owner_all);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", (bin.string() + ":" + path).c_str(), 1);
    auto manifest = loadShadertoy(dir);
    ASSERT_TRUE(manifest) << manifest.error().text();
    auto plan = planPlayer(std::move(*manifest), MediaOptions{});
    ::setenv("PATH", path.c_str(), 1);
    ASSERT_TRUE(plan) << plan.error().text();

    RunActivity activity;
    PlayerDesc desc;
    desc.width = 1;
    desc.height = 1;
    const AttachedActivity attached(*context_, activity);
    auto player = Player::create(context_, std::move(*plan), desc);
    ASSERT_TRUE(player) << player.error().text();
    (*player)->step(fixedStep((*player)->frame(), 30.0));  // frame 0: decoded at open

    // The watchdog's side: waits for the render thread to publish the wait, then ends the decoder.
    std::atomic<bool> seen{false};
    RunActivity::Snapshot during;
    std::thread watchdog([&] {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
        while (std::chrono::steady_clock::now() < deadline) {
            const RunActivity::Snapshot now = activity.snapshot();
            if (now.phase == RunActivity::Phase::WaitingForInput) {
                during = now;
                seen = true;
                break;
            }
            std::this_thread::yield();
        }
        const std::string pid = readAll(dir / "stalled.pid");
        if (!pid.empty()) ::kill(std::stoi(pid), SIGKILL);
    });
    (*player)->step(fixedStep((*player)->frame(), 30.0));  // frame 1: its video frame never comes; ends when the decoder dies
    watchdog.join();
    EXPECT_TRUE(seen) << "the wait for the decoder was not published";
    EXPECT_STREQ(during.pass, "Image");
    EXPECT_EQ(during.frame, 1);
    EXPECT_EQ(activity.snapshot().phase, RunActivity::Phase::Idle);
}

}  // namespace
}  // namespace toyhost::testing
