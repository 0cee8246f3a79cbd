// VideoSource: a video channel decoded by an ffmpeg child process. The test videos are encoded
// losslessly (FFV1 in Matroska, and H.264 RGB at qp 0 in MP4, which has B-frames and an edit list)
// from raw frames that each say their index in red and blue; the top half has green 200 and the
// bottom half green 50, so the row order shows. Also the errors for files that are not videos, the
// child's clean-up, and the deterministic stand-in.
#include <gtest/gtest.h>

#include <unistd.h>

#include <csignal>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "DiagnosticText.h"
#include "Processes.h"
#include "TestFolder.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"
#include "media/VideoSource.h"
#include "media/VideoStream.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {

// 10 s at 10 fps: long enough that jumps of more than 30 frames restart ffmpeg with -ss.
constexpr int kWidth = 64, kHeight = 48, kFps = 10, kFrames = 100;

bool haveFfmpeg() { return findExecutable("ffmpeg") && findExecutable("ffprobe"); }

struct Encoding {
    const char* name;
    const char* file;
    const char* codec;  // ffmpeg arguments
};
const Encoding kEncodings[] = {
    {"Ffv1Matroska", "indexed.mkv", "-c:v ffv1"},
    {"H264Mp4", "indexed.mp4", "-c:v libx264rgb -qp 0 -preset ultrafast -bf 2"},
};

// The parameter as gtest prints it (in test lists and `ctest -N`): the encoding's name, not the
// struct's bytes (which hold pointers, different in every build).
void PrintTo(const Encoding& encoding, std::ostream* out) { *out << encoding.name; }

// Frame k: red 10 * (k % 25), blue 50 * (k / 25); green 200 on the top half, 50 below.
fs::path makeIndexedVideo(const TestFolder& folder, const Encoding& encoding) {
    const fs::path raw = folder.path / "frames.rgba";
    {
        std::ofstream out(raw, std::ios::binary);
        std::vector<char> frame(static_cast<std::size_t>(kWidth) * kHeight * 4);
        for (int k = 0; k < kFrames; ++k) {
            for (int y = 0; y < kHeight; ++y)  // y = 0 is the top row, as files and ffmpeg store it
                for (int x = 0; x < kWidth; ++x) {
                    char* p = &frame[(static_cast<std::size_t>(y) * kWidth + x) * 4];
                    p[0] = static_cast<char>(10 * (k % 25));
                    p[1] = static_cast<char>(y < kHeight / 2 ? 200 : 50);
                    p[2] = static_cast<char>(50 * (k / 25));
                    p[3] = static_cast<char>(255);
                }
            out.write(frame.data(), static_cast<std::streamsize>(frame.size()));
        }
    }
    const fs::path video = folder.path / encoding.file;
    const auto [code, output] = toyhost::testing::shell(
        "ffmpeg -v error -nostdin -y -f rawvideo -pix_fmt rgba -s 64x48 -r 10 -i '" + raw.string() + "' " +
        encoding.codec + " '" + video.string() + "' 2>&1");
    if (code != 0) return {};
    return video;
}

// The frame index a decoded frame encodes, after checking the frame is uniform in red and blue.
int frameIndexIn(const Image8& frame) {
    const std::uint8_t red = frame.rgba[0], blue = frame.rgba[2];
    for (std::size_t i = 0; i < frame.rgba.size(); i += 4)
        if (frame.rgba[i] != red || frame.rgba[i + 2] != blue) return -1;
    return red / 10 + 25 * (blue / 50);
}

int indexAt(VideoSource& video, double seconds) {
    Result<const Image8*> frame = video.frameAt(seconds);
    if (!frame) {
        ADD_FAILURE() << frame.error().text();
        return -1;
    }
    return frameIndexIn(**frame);
}

struct ChildInfo {
    int pid;
    std::string command;  // "ffmpeg S": name and state (Z for a zombie: still listed until reaped)
};

// This process's children, zombies included.
std::vector<ChildInfo> children() {
    std::vector<ChildInfo> found;
    const std::string self = std::to_string(::getpid());
    for (const auto& entry : fs::directory_iterator("/proc")) {
        std::ifstream stat(entry.path() / "stat");
        std::string line;
        if (!std::getline(stat, line)) continue;
        const std::size_t close = line.rfind(')');
        if (close == std::string::npos) continue;
        // "pid (comm) state ppid ..."
        std::istringstream rest(line.substr(close + 2));
        std::string state, parent;
        rest >> state >> parent;
        if (parent == self)
            found.push_back({std::stoi(line), line.substr(line.find('(') + 1, close - line.find('(') - 1) + " " + state});
    }
    return found;
}

}  // namespace

class VideoSourceTest : public ::testing::TestWithParam<Encoding> {
protected:
    void SetUp() override {
        if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
        path = makeIndexedVideo(folder, GetParam());
        if (path.empty()) GTEST_SKIP() << "this ffmpeg cannot encode " << GetParam().codec;
        Result<std::unique_ptr<VideoSource>> opened = VideoSource::openFile(path);
        ASSERT_TRUE(opened) << opened.error().text();
        video = std::move(*opened);
    }
    TestFolder folder;
    fs::path path;
    std::unique_ptr<VideoSource> video;
};

INSTANTIATE_TEST_SUITE_P(Encodings, VideoSourceTest, ::testing::ValuesIn(kEncodings),
                         [](const ::testing::TestParamInfo<Encoding>& info) { return std::string(info.param.name); });

TEST_P(VideoSourceTest, ProbesSizeFrameRateAndDuration) {
    EXPECT_EQ(video->width(), kWidth);
    EXPECT_EQ(video->height(), kHeight);
    EXPECT_DOUBLE_EQ(video->fps(), kFps);
    EXPECT_EQ(video->frameCount(), kFrames);
    EXPECT_DOUBLE_EQ(video->duration(), 10.0);
    EXPECT_FALSE(video->live());
    EXPECT_EQ(frameIndexIn(video->frame()), 0);  // frame 0 is decoded at open
}

TEST_P(VideoSourceTest, FrameAtTimeTIsFrameFloorOfTTimesFps) {
    for (double t : {0.0, 0.05, 0.1, 0.35, 0.999, 1.0, 1.3, 2.6, 7.45, 9.99}) {
        EXPECT_EQ(indexAt(*video, t), static_cast<int>(std::floor(t * kFps + 1e-6))) << "t = " << t;
        EXPECT_EQ(video->frameIndexAt(t), static_cast<int>(std::floor(t * kFps + 1e-6)));
    }
    EXPECT_EQ(video->frame().width, kWidth);
    EXPECT_EQ(video->frame().height, kHeight);
}

TEST_P(VideoSourceTest, PlaybackPastTheEndLoopsWithoutRestartingTheDecoder) {
    // 60 fps rendering of a 10 fps video for two loops and a bit, as a capture at a fixed step does it.
    for (int frame = 0; frame < 1300; ++frame) {
        const double t = frame / 60.0;
        ASSERT_EQ(indexAt(*video, t), (frame / 6) % kFrames) << "t = " << t;
    }
    EXPECT_EQ(video->decoderStarts(), 1);  // the loop continues inside ffmpeg (-stream_loop)
    EXPECT_NEAR(video->playbackTime(10.35), 0.35, 1e-9);  // iChannelTime wraps with the video
    EXPECT_NEAR(video->playbackTime(25.5), 5.5, 1e-9);
}

TEST_P(VideoSourceTest, SeekingBackwardsAndJumpingGiveTheRightFrames) {
    const struct {
        double t;
        int frame;
        int starts;  // decoder starts so far: a jump of more than 30 frames restarts it
    } steps[] = {
        {1.5, 15, 1},     // 14 frames ahead: read through
        {0.3, 3, 2},      // back: restart with -ss
        {1.0, 10, 2},     // ahead again
        {0.0, 0, 3},      // back to the start: restart, looping
        {123.45, 34, 4},  // frame 1234 mod 100, 33 ahead: restart
        {1.2, 12, 5},
        {9.9, 99, 6},
        {9.0, 90, 7},
    };
    for (const auto& step : steps) {
        EXPECT_EQ(indexAt(*video, step.t), step.frame) << "t = " << step.t;
        EXPECT_EQ(video->decoderStarts(), step.starts) << "t = " << step.t;
    }
}

TEST_P(VideoSourceTest, AStartInTheMiddleWrapsAtTheEnd) {
    // A shard or resumed run starts mid-video: ffmpeg starts with -ss and is restarted at the end.
    const struct {
        double t;
        int frame;
        int starts;
    } steps[] = {{9.7, 97, 2}, {9.8, 98, 2}, {9.9, 99, 2}, {10.0, 0, 3}, {10.1, 1, 3},
                 {19.9, 99, 4}, {20.0, 0, 5}, {20.5, 5, 5}};
    for (const auto& step : steps) {
        EXPECT_EQ(indexAt(*video, step.t), step.frame) << "t = " << step.t;
        EXPECT_EQ(video->decoderStarts(), step.starts) << "t = " << step.t;
    }
}

TEST_P(VideoSourceTest, RowsAreBottomFirst) {
    const Image8& frame = video->frame();
    const std::size_t row = static_cast<std::size_t>(frame.width) * 4;
    EXPECT_EQ(frame.rgba[1], 50);                                          // row 0: the picture's bottom
    EXPECT_EQ(frame.rgba[(static_cast<std::size_t>(frame.height) - 1) * row + 1], 200);  // last row: its top
}

TEST_P(VideoSourceTest, DestroyingTheSourceKillsAndReapsFfmpeg) {
    const std::vector<ChildInfo> before = children();
    ASSERT_EQ(before.size(), 1u) << "expected the decoder as the only child";
    EXPECT_EQ(before[0].command.rfind("ffmpeg", 0), 0u) << before[0].command;
    video.reset();
    const std::vector<ChildInfo> after = children();
    EXPECT_TRUE(after.empty()) << after.front().command;
}

TEST_P(VideoSourceTest, ADecoderThatDiesIsAnErrorNamingTheFileThenARestart) {
    const std::vector<ChildInfo> decoder = children();
    ASSERT_EQ(decoder.size(), 1u);
    ASSERT_EQ(::kill(decoder[0].pid, SIGKILL), 0);
    // Frames already in the pipe still arrive (at most its 1 MiB: 85 of these); then the end of
    // the stream is an error.
    Result<const Image8*> frame = video->frameAt(0.0);
    int reached = 1;
    for (; reached < 2000 && frame; ++reached) frame = video->frameAt(reached / double(kFps));
    ASSERT_FALSE(frame) << "no error after " << reached << " frames";
    EXPECT_EQ(frame.error().first().file, path.string());
    EXPECT_EQ(frame.error().first().message.rfind("ffmpeg stopped decoding at frame ", 0), 0u)
        << frame.error().first().message;
    const int lastGood = (reached - 2) % kFrames;
    EXPECT_EQ(frameIndexIn(video->frame()), lastGood);  // the last good frame stays
    EXPECT_TRUE(children().empty());                    // the dead decoder was reaped
    // The next request for another frame starts a new decoder at that frame.
    const int next = (lastGood + 50) % kFrames;
    EXPECT_EQ(indexAt(*video, next / double(kFps)), next);
    EXPECT_EQ(video->decoderStarts(), 2);
}

// ---- VideoStream: the same file decoded ahead on its own thread ------------------------------

class VideoStreamTest : public VideoSourceTest {
protected:
    void SetUp() override {
        VideoSourceTest::SetUp();
        if (IsSkipped() || HasFatalFailure()) return;
        video.reset();  // one decoder at a time, so the children() checks see the stream's own
        Result<std::shared_ptr<VideoStream>> opened = VideoStream::openFile(path);
        ASSERT_TRUE(opened) << opened.error().text();
        stream = std::move(*opened);
    }
    int shown(std::int64_t index, const InputWait& wait = {}) {
        Result<const Image8*> frame = stream->frame(index, wait);
        if (!frame) {
            ADD_FAILURE() << frame.error().text();
            return -1;
        }
        return frameIndexIn(**frame);
    }
    std::shared_ptr<VideoStream> stream;
};

INSTANTIATE_TEST_SUITE_P(Encodings, VideoStreamTest, ::testing::ValuesIn(kEncodings),
                         [](const ::testing::TestParamInfo<Encoding>& info) { return std::string(info.param.name); });

TEST_P(VideoStreamTest, FramesAheadAreDecodedBeforeTheyAreAskedFor) {
    EXPECT_EQ(frameIndexIn(stream->current()), 0);  // frame 0 is decoded at open
    EXPECT_EQ(stream->queueCapacity(), 3);           // defaults::kVideoAheadFrames for a small frame
    stream->waitUntilQueued();
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(shown(k), k);
    EXPECT_EQ(stream->waits(), 0u) << "the render thread waited for frames the decoder had ready";
}

TEST_P(VideoStreamTest, FrameIIsTheFilesFrameIWhateverTheOrderAndPace) {
    // A fixed pseudo-random walk: steps forward of 0..4 frames (rendering faster or slower than the
    // video), jumps back, far jumps and the loop, with waits for the queue between some of them.
    std::mt19937 random(1234);
    std::int64_t index = 0;
    for (int i = 0; i < 400; ++i) {
        const int choice = static_cast<int>(random() % 20);
        if (choice == 0) index = static_cast<std::int64_t>(random() % kFrames);             // anywhere
        else if (choice == 1) index = (index + kFrames - 1 - random() % 5) % kFrames;       // a little back
        else index = (index + random() % 5) % kFrames;                                      // forward
        if (random() % 7 == 0) stream->waitUntilQueued();
        ASSERT_EQ(shown(index), index) << "step " << i;
    }
    EXPECT_GT(stream->decoderStarts(), 1);  // the jumps restarted ffmpeg
}

TEST_P(VideoStreamTest, PlaybackThroughTheLoopKeepsOneDecoder) {
    for (int frame = 0; frame < 1300; ++frame)
        ASSERT_EQ(shown(stream->frameIndexAt(frame / 60.0)), (frame / 6) % kFrames) << "frame " << frame;
    EXPECT_EQ(stream->decoderStarts(), 1);  // the loop continues inside ffmpeg (-stream_loop)
}

TEST_P(VideoStreamTest, AWaitIsPublishedAndEndsIdle) {
    // Far ahead: the decoder starts over there, and the render thread waits for it.
    RunActivity activity;
    const std::uint64_t before = stream->waits();
    EXPECT_EQ(shown(70, InputWait{&activity, "Image", 12}), 70);
    EXPECT_EQ(stream->waits(), before + 1);
    EXPECT_EQ(activity.snapshot().phase, RunActivity::Phase::Idle);  // published while it lasted, then idle
}

TEST_P(VideoStreamTest, DestroyingTheStreamStopsItsThreadAndReapsFfmpeg) {
    stream->waitUntilQueued();  // the thread now waits for room in the queue, ffmpeg for its pipe
    ASSERT_EQ(children().size(), 1u);
    stream.reset();
    EXPECT_TRUE(children().empty());
}

TEST_P(VideoStreamTest, ADecoderThatDiesIsAnErrorThenTheNextFrameStartsAnother) {
    stream->waitUntilQueued();  // frames 1..3 are queued
    const std::vector<ChildInfo> decoder = children();
    ASSERT_EQ(decoder.size(), 1u);
    ASSERT_EQ(::kill(decoder[0].pid, SIGKILL), 0);
    // What was queued or in the pipe still arrives; then the end of the stream is an error naming
    // the file.
    Result<const Image8*> frame = stream->frame(1);
    int reached = 1;
    for (; reached < 2000 && frame; ++reached) frame = stream->frame(reached % kFrames);
    ASSERT_FALSE(frame) << "no error after " << reached << " frames";
    EXPECT_EQ(frame.error().first().file, path.string());
    const int lastGood = (reached - 2) % kFrames;
    EXPECT_GE(reached - 2, 3);
    EXPECT_EQ(frameIndexIn(stream->current()), lastGood);  // the last good frame stays
    EXPECT_TRUE(children().empty());                      // the dead decoder was reaped
    const int next = (lastGood + 50) % kFrames;
    EXPECT_EQ(shown(next), next);
    EXPECT_EQ(stream->decoderStarts(), 2);
}

TEST(VideoStream, AFrameTooLargeForTheByteBudgetQueuesFewerFrames) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    // 4096x2304 RGBA is 37.7 MB a frame: two fit in defaults::kVideoAheadBytes (96 MiB), not three.
    const fs::path big = folder.path / "big.mkv";
    ASSERT_EQ(toyhost::testing::shell("ffmpeg -v error -nostdin -f lavfi -i color=c=red:s=4096x2304:r=1:d=3 -c:v ffv1 '" +
                                      big.string() + "'").first, 0);
    Result<std::shared_ptr<VideoStream>> opened = VideoStream::openFile(big);
    ASSERT_TRUE(opened) << opened.error().text();
    EXPECT_EQ((*opened)->queueCapacity(), 2);
}

TEST(VideoSource, AMissingFileIsOneErrorNamingIt) {
    TestFolder folder;
    const fs::path missing = folder.path / "nowhere.mp4";
    Result<std::unique_ptr<VideoSource>> opened = VideoSource::openFile(missing);
    ASSERT_FALSE(opened);
    ASSERT_EQ(opened.error().diagnostics.size(), 1u);
    EXPECT_EQ(toyhost::testing::plainText(opened.error()), missing.string() + ": video file not found");
}

TEST(VideoSource, FilesThatAreNotVideosFailWithAClearMessage) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    const fs::path text = folder.write("notes.mp4", "this is not a video\n");
    Result<std::unique_ptr<VideoSource>> opened = VideoSource::openFile(text);
    ASSERT_FALSE(opened);
    ASSERT_EQ(opened.error().diagnostics.size(), 1u);
    EXPECT_EQ(opened.error().first().file, text.string());
    // ffprobe's own words, without its "[mov,mp4,... @ 0x...]" prefixes ("moov atom not found" for .mp4).
    const std::string message = opened.error().first().message;
    EXPECT_EQ(message.rfind("cannot read as a video: ", 0), 0u) << message;
    EXPECT_NE(message.find("Invalid data found when processing input"), std::string::npos) << message;
    EXPECT_EQ(message.find(" @ 0x"), std::string::npos) << message;
    EXPECT_EQ(message.find(text.string()), std::string::npos) << message;  // named once, as the file

    const fs::path sound = folder.path / "tone.wav";
    ASSERT_EQ(toyhost::testing::shell("ffmpeg -v error -nostdin -f lavfi -i sine=d=0.2 '" + sound.string() + "'").first, 0);
    opened = VideoSource::openFile(sound);
    ASSERT_FALSE(opened);
    EXPECT_EQ(toyhost::testing::plainText(opened.error()), sound.string() + ": not a video: it has no video stream");

    const fs::path still = folder.path / "still.png";
    ASSERT_EQ(toyhost::testing::shell("ffmpeg -v error -nostdin -f lavfi -i testsrc=s=32x32 -frames:v 1 '" +
                                      still.string() + "'").first, 0);
    opened = VideoSource::openFile(still);
    ASSERT_FALSE(opened);
    EXPECT_EQ(toyhost::testing::plainText(opened.error()),
              still.string() + ": not a video: it is a still image (bind it as a texture)");
    EXPECT_TRUE(children().empty());
}

TEST(VideoSource, AMissingCameraIsOneErrorNamingTheDevice) {
    Result<std::unique_ptr<VideoSource>> opened = VideoSource::openDevice("/dev/video-toyhost-none");
    ASSERT_FALSE(opened);
    EXPECT_EQ(toyhost::testing::plainText(opened.error()),
              "/dev/video-toyhost-none: camera not found: No such file or directory");
}

TEST(VideoStandIn, IsDeterministicMovesWithTimeAndLoops) {
    Image8 a, b;
    videoStandInFrame(1.25, a);
    EXPECT_EQ(a.width, defaults::kVideoStandInWidth);
    EXPECT_EQ(a.height, defaults::kVideoStandInHeight);
    ASSERT_EQ(a.rgba.size(), static_cast<std::size_t>(defaults::kVideoStandInWidth) * defaults::kVideoStandInHeight * 4);
    videoStandInFrame(1.25, b);
    EXPECT_EQ(a.rgba, b.rgba);
    videoStandInFrame(1.25 + 1.0 / 30, b);
    EXPECT_NE(a.rgba, b.rgba);
    videoStandInFrame(1.25 + kVideoStandInDuration, b);
    EXPECT_EQ(a.rgba, b.rgba);
    EXPECT_NEAR(videoStandInPlaybackTime(12.5), 2.5, 1e-9);

    // The bottom quarter is a grey ramp, the top three quarters colour bars: a flip shows.
    const std::uint8_t* bottom = a.rgba.data();
    EXPECT_TRUE(bottom[0] == bottom[1] && bottom[1] == bottom[2]);
    bool colour = false;
    const std::uint8_t* top = a.rgba.data() + (a.rgba.size() - static_cast<std::size_t>(a.width) * 4);
    for (int x = 0; x < a.width; ++x) colour |= top[x * 4] != top[x * 4 + 1] || top[x * 4 + 1] != top[x * 4 + 2];
    EXPECT_TRUE(colour);
}

TEST(VideoStandIn, TheDiscIsClippedAtTheRightAndTopEdges) {
    // At 2.5 s the disc is at the right end of its path (centre x 604, radius 36) and at y 180: its
    // rightmost column, x = 640, is outside the frame; written anyway, it would land on the first
    // pixel of the next row (and at the top end of its path, past the last row).
    Image8 frame;
    videoStandInFrame(2.5, frame);
    const std::size_t row = static_cast<std::size_t>(defaults::kVideoStandInWidth) * 4;
    const std::uint8_t* next = frame.rgba.data() + 181 * row;  // x = 0 of the row above the centre
    // The colour bars there (shifted by 160 px at 2.5 s: bar 2, cyan), not the disc's white rim.
    EXPECT_EQ(int(next[0]), 0);
    EXPECT_EQ(int(next[1]), 191);
    EXPECT_EQ(int(next[2]), 191);
}

TEST(VideoStandIn, ReusesTheFrameBuffer) {
    Image8 frame;
    videoStandInFrame(0.0, frame);
    const std::uint8_t* buffer = frame.rgba.data();
    for (int i = 1; i < 50; ++i) videoStandInFrame(i / 60.0, frame);
    EXPECT_EQ(frame.rgba.data(), buffer);
}
