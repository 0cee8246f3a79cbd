// --out movie.mp4|.webm: ffmpeg receives every captured frame, and the video has the requested
// frame count and size (checked with ffprobe). A failing ffmpeg fails the run with its message
// and leaves no file. Skips when ffmpeg or ffprobe is not installed (CI installs both).
#include "GlTestSupport.h"
#include "Processes.h"

#include <csignal>
#include <cstdlib>
#include <cstring>

#include "core/ChildProcess.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

#define REQUIRE_FFMPEG()                                                                          \
    do {                                                                                          \
        if (!findExecutable("ffmpeg") || !findExecutable("ffprobe"))                              \
            GTEST_FAIL() << "ffmpeg/ffprobe not installed (apt-get install ffmpeg)";              \
    } while (0)

// "frames,width,height" of the first video stream, counted by decoding.
std::string probe(const fs::path& video) {
    CommandResult result;
    const std::string command = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                "stream=nb_read_frames,width,height -of csv=p=0:nk=1 " + quoted(video) + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return "popen failed";
    char chunk[512];
    std::string out;
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, pipe)) > 0) out.append(chunk, n);
    pclose(pipe);
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
    return out;
}

const fs::path kProbe = sourceDir() / "shadertoys/pingpong-probe";

struct VideoCase {
    const char* file;
    const char* size;
    int frames;
    int every;
    const char* expected;  // width,height,frames as ffprobe prints them
    friend void PrintTo(const VideoCase& c, std::ostream* os) { *os << c.file; }
};

class VideoOutput : public ::testing::TestWithParam<VideoCase> {};

TEST_P(VideoOutput, HasTheRequestedFrameCountAndSize) {
    REQUIRE_FFMPEG();
    const VideoCase& c = GetParam();
    const fs::path dir = freshOutputDir(std::string("video/") + c.file);
    auto result = runToyhost("run " + quoted(kProbe) + " --size " + c.size + " --frames " + std::to_string(c.frames) +
                             " --capture-every " + std::to_string(c.every) + " --quiet --out " + quoted(dir / c.file));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(probe(dir / c.file), c.expected);
    for (const auto& entry : fs::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), c.file) << "left behind: " << entry.path();
}

INSTANTIATE_TEST_SUITE_P(Containers, VideoOutput,
                         ::testing::Values(VideoCase{"movie.mp4", "64x36", 12, 1, "64,36,12"},
                                           VideoCase{"odd.mov", "33x17", 7, 1, "33,17,7"},
                                           VideoCase{"every3.webm", "48x32", 10, 3, "48,32,4"}),
                         [](const auto& info) {
                             std::string name = info.param.file;
                             for (char& ch : name) if (ch == '.') ch = '_';
                             return name;
                         });

TEST(VideoOutputErrors, AFailingEncoderFailsTheRunAndLeavesNoFile) {
    REQUIRE_FFMPEG();
    const fs::path dir = freshOutputDir("video-error");
    auto result = runToyhost("run " + quoted(kProbe) + " --size 32x16 --frames 3 --quiet --codec no-such-encoder --out " +
                             quoted(dir / "bad.mp4"));
    EXPECT_EQ(result.exitCode, 1) << result.output;
    EXPECT_NE(result.output.find("bad.mp4"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("no-such-encoder"), std::string::npos) << result.output;
    EXPECT_TRUE(fs::is_empty(dir)) << "output or temporary files were left behind";
}

TEST(VideoOutputErrors, VideoOptionsNeedAVideoOutput) {
    const fs::path dir = freshOutputDir("video-options");
    auto result = runToyhost("run " + quoted(kProbe) + " --size 32x16 --quiet --video-quality 20 --out " +
                             quoted(dir / "f.png"));
    EXPECT_EQ(result.exitCode, 2) << "a usage error";
    EXPECT_NE(result.output.find("--video-quality"), std::string::npos) << result.output;
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// Ctrl-C (SIGINT) stops the run before its next frame: exit 130, the video being encoded is
// discarded with its temporary files, and nothing is left in the folder.
TEST(VideoInterrupt, SigintDiscardsThePartialVideo) {
    if (!findExecutable("ffmpeg") || !findExecutable("timeout")) GTEST_FAIL() << "needs ffmpeg and timeout";
    const fs::path dir = freshOutputDir("video/interrupt");
    // --foreground: the signal goes to toyhost only (ffmpeg must not see it first).
    auto run = runCommand("timeout", "--foreground --preserve-status -s INT 2 '" + toyhostBinary().string() + "' run '" +
                                         (sourceDir() / "shadertoys/pingpong-probe").string() +
                                         "' --size 64x32 --frames 100000000 --finish-each-frame --quiet --out '" +
                                         (dir / "long.mp4").string() + "'");
    EXPECT_EQ(run.exitCode, 130) << run.output;
    EXPECT_NE(run.output.find("interrupted after"), std::string::npos) << run.output;
    EXPECT_TRUE(fs::is_empty(dir)) << "files were left behind";
}

// The processes of process group `group` that still run (zombies, dead but not yet reaped by
// whoever adopted them, do not count), from /proc/PID/stat: "pid (name) state ppid pgrp ...".
int runningInGroup(pid_t group) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator("/proc")) {
        std::ifstream in(entry.path() / "stat");
        std::string text;
        if (!std::getline(in, text)) continue;
        const std::size_t close = text.rfind(')');
        if (close == std::string::npos) continue;
        std::istringstream rest(text.substr(close + 1));
        char state = 0;
        long parent = 0, pgrp = 0;
        if (rest >> state >> parent >> pgrp && pgrp == group && state != 'Z' && state != 'X') ++count;
    }
    return count;
}

// Once a regression (issue 46): with an ffmpeg that never reads (here a script that sleeps, whose
// sleep holds the pipe open after the script is killed), the stop notice was printed and the run
// went on until SIGKILL: the encoder thread stayed blocked writing the frame. Now a stop ends the run
// within the grace period, ffmpeg's whole process group with it, and leaves no file (the hidden
// temporary video and ffmpeg's log included).
TEST(VideoInterrupt, AStopEndsARunWhoseEncoderStalled) {
    const fs::path dir = freshOutputDir("video/stalled");
    fs::create_directories(dir / "bin");
    fs::create_directories(dir / "out");
    fs::create_directories(dir / "tmp");
    writeFile(dir / "bin/ffmpeg", "#!/bin/sh\necho $$ > '" + (dir / "ffmpeg.pid").string() + "'\nsleep 600\n");
    fs::permissions(dir / "bin/ffmpeg", fs::perms::owner_all);
    for (const int signal : {SIGINT, SIGTERM}) {
        fs::remove(dir / "ffmpeg.pid");
        // The environment the run inherits: the stalling ffmpeg first on PATH, ffmpeg's log in tmp.
        const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin";
        const std::string tmp = std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "";
        ::setenv("PATH", ((dir / "bin").string() + ":" + path).c_str(), 1);
        ::setenv("TMPDIR", (dir / "tmp").c_str(), 1);
        BackgroundProcess run(toyhostBinary(),
                              {"run", (sourceDir() / "shadertoys/bench-trivial").string(), "--headless", "--size",
                               "320x180", "--frames", "100000000", "--out", (dir / "out/m.mp4").string()},
                              dir / "run.log");
        ::setenv("PATH", path.c_str(), 1);
        if (tmp.empty()) ::unsetenv("TMPDIR");
        else ::setenv("TMPDIR", tmp.c_str(), 1);
        // The run started: its first frame started ffmpeg, which took none of it.
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
        while (!fs::exists(dir / "ffmpeg.pid") && run.running() && std::chrono::steady_clock::now() < deadline)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        ASSERT_TRUE(fs::exists(dir / "ffmpeg.pid")) << run.log();
        pid_t group = 0;
        std::ifstream(dir / "ffmpeg.pid") >> group;
        ASSERT_GT(group, 0);
        run.signal(signal);
        EXPECT_EQ(run.wait(60), 128 + signal) << strsignal(signal) << ": " << run.log();
        EXPECT_NE(run.log().find("the unfinished video was discarded"), std::string::npos) << run.log();
        EXPECT_EQ(runningInGroup(group), 0) << "ffmpeg's process group outlived the run";
        ::kill(-group, SIGKILL);  // what the old code left
        EXPECT_TRUE(fs::is_empty(dir / "out")) << "files were left behind";
        EXPECT_TRUE(fs::is_empty(dir / "tmp")) << "ffmpeg's log was left behind";
    }
}

}  // namespace
}  // namespace toyhost::testing
