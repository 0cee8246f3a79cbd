// sequence/FrameCheck and sequence/JoinFrames: frames are judged by decoding them (a cut PNG is
// truncated, a PNG with a broken body undecodable, an empty EXR truncated), shard by shard; a
// complete sequence joins into a video whose frame count ffprobe confirms. No GL.
#include <gtest/gtest.h>

#include <climits>
#include <cstdio>
#include <fstream>
#include <vector>

#include "TestFolder.h"
#include "capture/WavFile.h"
#include "image/ImageWriters.h"
#include "farm/frames/FrameCheck.h"
#include "farm/frames/JoinFrames.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {

std::vector<std::uint8_t> picture(int w, int h, int seed) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(i * 7 + seed * 31);
    return rgba;
}

// The first line ffprobe prints for `arguments` on `file`.
std::string probe(const std::string& arguments, const fs::path& file) {
    std::FILE* pipe = popen(("ffprobe -v error " + arguments + " '" + file.string() + "'").c_str(), "r");
    if (!pipe) return "";
    char line[256] = {};
    std::string all;
    while (std::fgets(line, sizeof line, pipe)) all += line;
    pclose(pipe);
    return all;
}

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), {});
}

}  // namespace

TEST(FrameCheck, DecodesEveryFrameAndReportsItsStatePerShard) {
    toyhost::testing::TestFolder dir;
    for (int f = 0; f < 6; ++f) {
        const auto rgba = picture(16, 9, f);
        ASSERT_TRUE(writePng(dir.path / ("f_" + std::to_string(f) + ".png"), 16, 9, rgba));
    }
    // Frame 2 cut in half (a writer killed mid-file without atomic renames), frame 3 gone, frame
    // 4 complete in length but with its image data overwritten.
    const std::string whole = bytesOf(dir.path / "f_2.png");
    dir.write("f_2.png", whole.substr(0, whole.size() / 2));
    fs::remove(dir.path / "f_3.png");
    std::string broken = bytesOf(dir.path / "f_4.png");
    for (std::size_t i = 60; i < broken.size() - 20; ++i) broken[i] = 'x';
    dir.write("f_4.png", broken);

    std::string reason;
    EXPECT_EQ(checkFrameFile(dir.path / "f_0.png", reason), farm::FrameState::Ok);
    EXPECT_EQ(checkFrameFile(dir.path / "f_2.png", reason), farm::FrameState::Truncated);
    EXPECT_EQ(checkFrameFile(dir.path / "f_3.png", reason), farm::FrameState::Missing);
    reason.clear();
    EXPECT_EQ(checkFrameFile(dir.path / "f_4.png", reason), farm::FrameState::Undecodable);
    EXPECT_FALSE(reason.empty());

    farm::FrameLayout layout;
    layout.frameDir = dir.path;
    layout.frameName = "f_%d.png";
    layout.frames = 6;
    layout.shards = 2;
    const farm::FarmStatus status = checkFarm(layout);
    ASSERT_EQ(status.shards.size(), 2u);
    EXPECT_EQ(status.shards[0].good, 2);
    EXPECT_EQ(status.shards[1].good, 1);
    EXPECT_EQ(farm::frameList(status.badSpans()), "2-4");
    EXPECT_EQ(status.shards[1].expected, 3);
    EXPECT_FALSE(status.complete());
}

TEST(FrameCheck, ExrFramesAreReadBack) {
    toyhost::testing::TestFolder dir;
    std::vector<float> rgba(8 * 4 * 4, 0.5f);
    ASSERT_TRUE(writeExr(dir.path / "f.exr", 8, 4, rgba));
    std::string reason;
    EXPECT_EQ(checkFrameFile(dir.path / "f.exr", reason), farm::FrameState::Ok);
    const std::string whole = bytesOf(dir.path / "f.exr");
    dir.write("cut.exr", whole.substr(0, whole.size() - 40));
    EXPECT_NE(checkFrameFile(dir.path / "cut.exr", reason), farm::FrameState::Ok);
    dir.write("empty.exr", "");
    EXPECT_EQ(checkFrameFile(dir.path / "empty.exr", reason), farm::FrameState::Truncated);
}

TEST(JoinFrames, EncodesTheSequenceAndRefusesMixedSizes) {
    toyhost::testing::TestFolder dir;
    std::vector<fs::path> frames;
    for (int f = 0; f < 5; ++f) {
        frames.push_back(dir.path / ("f_" + std::to_string(f) + ".png"));
        ASSERT_TRUE(writePng(frames.back(), 16, 8, picture(16, 8, f)));
    }
    ASSERT_TRUE(joinFrames(frames, dir.path / "movie.mp4", 30, {}));
    std::FILE* probe = popen(("ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
                              "-of csv=p=0 '" + (dir.path / "movie.mp4").string() + "'").c_str(), "r");
    ASSERT_NE(probe, nullptr);
    char line[64] = {};
    ASSERT_NE(std::fgets(line, sizeof line, probe), nullptr);
    pclose(probe);
    EXPECT_EQ(std::atoi(line), 5);

    ASSERT_TRUE(writePng(frames[3], 8, 8, picture(8, 8, 3)));
    Status mixed = joinFrames(frames, dir.path / "mixed.mp4", 30, {});
    ASSERT_FALSE(mixed);
    EXPECT_NE(mixed.error().text().find("f_3.png"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir.path / "mixed.mp4"));
}

TEST(JoinFrames, MuxesTheSoundTrack) {
    toyhost::testing::TestFolder dir;
    std::vector<fs::path> frames;
    for (int f = 0; f < 3; ++f) {
        frames.push_back(dir.path / ("f_" + std::to_string(f) + ".png"));
        ASSERT_TRUE(writePng(frames.back(), 16, 8, picture(16, 8, f)));
    }
    std::vector<float> stereo(2 * 4410, 0.25f);  // 0.1 s at 44100 Hz
    ASSERT_TRUE(writeWav16(dir.path / "track.wav", stereo, 44100));
    VideoSettings settings;
    settings.audio = dir.path / "track.wav";
    ASSERT_TRUE(joinFrames(frames, dir.path / "movie.mp4", 30, settings));
    EXPECT_EQ(probe("-show_entries stream=codec_type -of csv=p=0", dir.path / "movie.mp4"), "video\naudio\n");
}

// `farm status --frames 2147483647` with 8 frames on disk stat'ed 2^31 names one by one (still
// checking after 300 s) and listed each missing one: the folder is listed once and what is absent
// is counted in runs, so this answers at once.
TEST(FrameCheck, AHugeFrameCountWithFewFilesOnDiskIsCountedNotWalked) {
    toyhost::testing::TestFolder dir;
    for (int f : {0, 1, 2, 3, 4, 5, 6, 100}) ASSERT_TRUE(writePng(dir.path / ("f_" + std::to_string(f) + ".png"), 4, 2, picture(4, 2, f)));
    dir.write("f_7.png", "not a picture");
    dir.write("notes.txt", "other files are no frames");
    farm::FrameLayout layout;
    layout.frameDir = dir.path;
    layout.frameName = "f_%d.png";
    layout.frames = INT_MAX;
    layout.shards = 2;
    const farm::FarmStatus status = checkFarm(layout);
    ASSERT_EQ(status.shards.size(), 2u);
    EXPECT_EQ(status.shards[0].good, 8);
    EXPECT_EQ(status.shards[0].expected, INT_MAX / 2);
    EXPECT_EQ(status.shards[0].bad(), INT_MAX / 2 - 8);
    EXPECT_EQ(status.shards[1].good, 0);
    EXPECT_EQ(status.shards[1].bad(), INT_MAX - INT_MAX / 2);
    EXPECT_EQ(farm::frameList(status.badSpans()), "7-99, 101-2147483646");
    ASSERT_GE(status.shards[0].problems.size(), 2u);
    EXPECT_EQ(status.shards[0].problems[0].state, farm::FrameState::Truncated);  // f_7.png: text, no IEND
    EXPECT_EQ(status.shards[0].problems[1].state, farm::FrameState::Missing);
    EXPECT_EQ(status.shards[0].problems[1].frame, 8);
    EXPECT_EQ(status.shards[0].problems[1].lastFrame(), 99);
}

// A 3 GB frame was read whole (41 s, then "out of memory" for the whole status): a file that large
// is judged from its first and last bytes. Sparse files: no disk space is used.
TEST(FrameCheck, AMultiGigabyteFrameIsCheckedFromItsEndsNotReadWhole) {
    toyhost::testing::TestFolder dir;
    const fs::path zeros = dir.path / "f_0.png";
    { std::ofstream(zeros) << ""; }
    fs::resize_file(zeros, std::uintmax_t(3) << 30);
    std::string reason;
    EXPECT_EQ(checkFrameFile(zeros, reason), farm::FrameState::Undecodable);
    EXPECT_NE(reason.find("not a PNG"), std::string::npos) << reason;

    // A PNG's signature at its start but no IEND at its end: truncated.
    const fs::path cut = dir.path / "f_1.png";
    const std::string signature = "\x89PNG\r\n\x1a\n";
    { std::ofstream(cut, std::ios::binary) << signature; }
    fs::resize_file(cut, std::uintmax_t(3) << 30);
    reason.clear();
    EXPECT_EQ(checkFrameFile(cut, reason), farm::FrameState::Truncated);
    EXPECT_NE(reason.find("IEND"), std::string::npos) << reason;
}

// ffmpeg's own words came for these, after every frame was decoded: toyhost's words come first.
TEST(JoinFrames, RefusesANonVideoOutAndASoundTrackThatIsNoSound) {
    toyhost::testing::TestFolder dir;
    std::vector<fs::path> frames{dir.path / "f_0.png"};
    ASSERT_TRUE(writePng(frames[0], 16, 8, picture(16, 8, 0)));
    Status png = joinFrames(frames, dir.path / "m.png", 30, {});
    ASSERT_FALSE(png);
    EXPECT_EQ(png.error().first().code, Code::Usage);
    EXPECT_NE(png.error().text().find(".mp4"), std::string::npos) << png.error().text();
    dir.write("notes.txt", "this is text, not a sound track\n");
    VideoSettings settings;
    settings.audio = dir.path / "notes.txt";
    Status text = joinFrames(frames, dir.path / "m.mp4", 30, settings);
    ASSERT_FALSE(text);
    EXPECT_EQ(text.error().first().code, Code::Usage);
    EXPECT_NE(text.error().text().find("not a sound file"), std::string::npos) << text.error().text();
    EXPECT_FALSE(fs::exists(dir.path / "m.mp4"));
}

// A stop request (the CLI's SIGINT/SIGTERM) ends the join between frames: no video, no hidden
// .partial, Code::Interrupted.
TEST(JoinFrames, AStopRequestEndsItLeavingNothing) {
    toyhost::testing::TestFolder dir;
    std::vector<fs::path> frames;
    for (int f = 0; f < 6; ++f) {
        frames.push_back(dir.path / ("f_" + std::to_string(f) + ".png"));
        ASSERT_TRUE(writePng(frames.back(), 16, 8, picture(16, 8, f)));
    }
    int asked = 0;
    Status stopped = joinFrames(frames, dir.path / "movie.mp4", 30, {}, [&] { return ++asked > 3; });
    ASSERT_FALSE(stopped);
    EXPECT_EQ(stopped.error().first().code, Code::Interrupted);
    for (const auto& entry : fs::directory_iterator(dir.path))
        EXPECT_NE(entry.path().extension(), ".mp4") << entry.path();
    for (const auto& entry : fs::directory_iterator(dir.path))
        EXPECT_NE(entry.path().filename().string()[0], '.') << "left behind: " << entry.path();
}
