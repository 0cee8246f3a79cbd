// Capture helpers without GL: float-to-8-bit conversion and row order of captured frames, the
// ffmpeg command line for each container, the progress line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

#include "capture/FrameBytes.h"
#include "capture/VideoEncoderChoice.h"
#include "capture/VideoSink.h"
#include "timing/ProgressLine.h"

using namespace toyhost;

namespace {

bool contains(const std::vector<std::string>& args, const std::vector<std::string>& run) {
    return std::search(args.begin(), args.end(), run.begin(), run.end()) != args.end();
}

}  // namespace

TEST(PixelConversion, FloatsAreClampedAndRoundedLikeAUnorm8Target) {
    const float values[8] = {-1.0f, 0.0f, 0.5f, 1.0f, 2.0f, 0.2f, std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::infinity()};
    CapturedFrame frame{0, 2, 1, PixelFormat::Rgba32f, std::vector<std::byte>(sizeof values)};
    std::memcpy(frame.pixels.data(), values, sizeof values);
    std::vector<std::uint8_t> scratch;
    const auto bytes = rgba8BottomUp(frame, scratch);
    EXPECT_EQ(std::vector<std::uint8_t>(bytes.begin(), bytes.end()),
              (std::vector<std::uint8_t>{0, 0, 128, 255, 255, 51, 0, 255}));
}

TEST(PixelConversion, Rgba8FramesPassThroughAndRowsFlip) {
    CapturedFrame frame{0, 1, 3, PixelFormat::Rgba8, std::vector<std::byte>(12)};
    for (int i = 0; i < 12; ++i) frame.pixels[i] = std::byte(i);
    std::vector<std::uint8_t> scratch, rows;
    const auto bytes = rgba8BottomUp(frame, scratch);
    EXPECT_EQ(static_cast<const void*>(bytes.data()), static_cast<const void*>(frame.pixels.data()));
    const auto top = rowsTopFirst(bytes, 1, 3, rows);
    EXPECT_EQ(std::vector<std::uint8_t>(top.begin(), top.end()),
              (std::vector<std::uint8_t>{8, 9, 10, 11, 4, 5, 6, 7, 0, 1, 2, 3}));
}

TEST(VideoArguments, Mp4IsH264FromRawRgbaOnStdin) {
    const auto args = ffmpegArguments({"/tmp/.m.mp4.1.0.partial", ".mp4", 640, 360, 30, {}});
    EXPECT_EQ(args.front(), "ffmpeg");
    EXPECT_EQ(args.back(), "/tmp/.m.mp4.1.0.partial");
    EXPECT_TRUE(contains(args, {"-f", "rawvideo", "-pix_fmt", "rgba", "-video_size", "640x360", "-framerate", "30",
                                "-i", "pipe:0"}));
    EXPECT_TRUE(contains(args, {"-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p"}));
    EXPECT_TRUE(contains(args, {"-f", "mp4"}));
    // Frames go down the pipe bottom row first (as GL reads them) and ffmpeg turns them: no copy.
    EXPECT_TRUE(contains(args, {"-vf", "vflip"}));
}

TEST(VideoArguments, OddSizesKeepFullChromaAndQualityIsTheCrf) {
    VideoSettings settings;
    settings.quality = 23;
    const auto args = ffmpegArguments({"x", ".mov", 33, 17, 59.94, settings});
    EXPECT_TRUE(contains(args, {"-crf", "23", "-pix_fmt", "yuv444p"}));
    EXPECT_TRUE(contains(args, {"-framerate", "59.94"}));
    EXPECT_TRUE(contains(args, {"-f", "mov"}));
}

TEST(VideoArguments, WebmIsVp9AndACustomCodecGetsOnlyWhatWasAsked) {
    const auto webm = ffmpegArguments({"x", ".webm", 64, 64, 60, {}});
    EXPECT_TRUE(contains(webm, {"-c:v", "libvpx-vp9", "-crf", "31", "-b:v", "0"}));
    EXPECT_TRUE(contains(webm, {"-f", "webm"}));
    VideoSettings custom;
    custom.codec = "ffv1";
    const auto mkv = ffmpegArguments({"x", ".mkv", 64, 64, 60, custom});
    EXPECT_TRUE(contains(mkv, {"-c:v", "ffv1"}));
    EXPECT_TRUE(contains(mkv, {"-f", "matroska"}));
    // Bit-exact output: no random Matroska UIDs, so the same frames give the same file.
    EXPECT_TRUE(contains(mkv, {"-fflags", "+bitexact", "-flags:v", "+bitexact"}));
    EXPECT_EQ(std::count(mkv.begin(), mkv.end(), "-crf"), 0);
    EXPECT_TRUE(contains(mkv, {"-vf", "vflip"}));
    VideoSettings vaapi;
    vaapi.codec = "h264_vaapi";
    const auto hw = ffmpegArguments({"x", ".mp4", 64, 64, 60, vaapi});
    EXPECT_TRUE(contains(hw, {"-vf", "vflip,format=nv12,hwupload"}));
    EXPECT_EQ(std::count(hw.begin(), hw.end(), "-vf"), 1);
}

TEST(ProgressLine, ShowsFramesRateEtaAndBytes) {
    RunProgress p;
    p.framesDone = 120;
    p.frames = 600;
    p.seconds = 24;
    p.bytesWritten = 13 * 1048576 + 1048576 / 2;
    EXPECT_EQ(formatProgressLine(p), "frame 120/600  5.0 fps  ETA 1:36  13.5 MiB written");
    p.bytesWritten = 0;
    p.seconds = 0;
    EXPECT_EQ(formatProgressLine(p), "frame 120/600  0.0 fps  ETA --:--");
    EXPECT_EQ(formatDuration(3723), "1:02:03");
    EXPECT_EQ(formatBytes(812), "812 B");
    EXPECT_EQ(formatBytes(3 * 1024 + 400), "3.4 KiB");
    EXPECT_EQ(formatBytes(std::uint64_t(3) << 30), "3.00 GiB");
}

TEST(VideoArguments, PresetPassesThroughAndHardwareEncodersGetTheirPixelPath) {
    VideoSettings fast;
    fast.preset = "ultrafast";
    EXPECT_TRUE(contains(ffmpegArguments({"/tmp/o", ".mp4", 64, 64, 30, fast}), {"-c:v", "libx264", "-preset", "ultrafast"}));
    VideoSettings vaapi;
    vaapi.codec = "h264_vaapi";
    const auto args = ffmpegArguments({"/tmp/o", ".mp4", 64, 64, 30, vaapi});
    EXPECT_TRUE(contains(args, {"-vaapi_device", "/dev/dri/renderD128"}));
    EXPECT_TRUE(contains(args, {"-c:v", "h264_vaapi", "-vf", "vflip,format=nv12,hwupload"}));
    VideoSettings nvenc;
    nvenc.codec = "h264_nvenc";
    nvenc.preset = "p1";
    EXPECT_TRUE(contains(ffmpegArguments({"/tmp/o", ".mp4", 64, 64, 30, nvenc}),
                         {"-c:v", "h264_nvenc", "-pix_fmt", "yuv420p", "-preset", "p1"}));
}

TEST(VideoEncoderChoice, AutoUsesAHardwareEncoderThatWorksElseSaysItFellBackToSoftware) {
    const VideoEncoderChoice choice = chooseAutoVideoEncoder(".mp4");
    const std::vector<std::string>& hardware = hardwareH264Encoders();
    if (choice.hardware) {
        // A machine whose ffmpeg encodes on its GPU: one of the candidates, said so.
        EXPECT_NE(std::find(hardware.begin(), hardware.end(), choice.codec), hardware.end());
        EXPECT_NE(choice.explanation().find("(hardware)"), std::string::npos);
    } else {
        // Here (no GPU, no /dev/dri): every candidate was tried and failed, libx264 is used, and
        // the notice says so.
        EXPECT_EQ(choice.codec, "libx264");
        EXPECT_EQ(choice.tried, hardware);
        EXPECT_NE(choice.explanation().find("no hardware encoder works here (tried h264_nvenc h264_vaapi h264_qsv)"),
                  std::string::npos)
            << choice.explanation();
    }
    // Cached: the second call runs no test encode and answers the same.
    const VideoEncoderChoice again = chooseAutoVideoEncoder(".mkv");
    EXPECT_EQ(again.codec, choice.codec);
    EXPECT_EQ(chooseAutoVideoEncoder(".webm").codec, "libvpx-vp9");
}

namespace {
// A stand-in ffmpeg that says which copy of it ran (into `marker`) and writes what it reads to its
// output (the last argument), as ffmpeg writes the video there.
void writeFakeFfmpeg(const std::filesystem::path& bin, const std::string& name, const std::filesystem::path& marker) {
    const std::filesystem::path script = bin / "ffmpeg";
    std::ofstream(script) << "#!/bin/sh\necho " << name << " > '" << marker.string()
                          << "'\nfor last; do :; done\ncat > \"$last\"\n";
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
}
}  // namespace

// The recorder makes its VideoSink on the render thread: ffmpeg must not start there (fork/exec,
// ffmpeg's start-up), but with the first frame, on the encoder thread that writes it. The copy of
// ffmpeg installed after start() returned is the one that runs.
TEST(VideoSink, FfmpegStartsWithTheFirstFrameNotWithTheSink) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("toyhost-videosink-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "bin");
    const fs::path marker = dir / "which-ffmpeg-ran";
    writeFakeFfmpeg(dir / "bin", "at-start", marker);
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", ((dir / "bin").string() + ":" + path).c_str(), 1);

    Result<std::unique_ptr<VideoSink>> sink = VideoSink::start(dir / "out.mp4", 2, 2, 30.0, {});
    ASSERT_TRUE(sink) << sink.error().text();
    EXPECT_FALSE((*sink)->launched());
    writeFakeFfmpeg(dir / "bin", "with-the-first-frame", marker);

    CapturedFrame frame{0, 2, 2, PixelFormat::Rgba8, std::vector<std::byte>(2 * 2 * 4, std::byte{7})};
    EncodeScratch scratch;
    const Status written = (*sink)->write(frame, scratch);
    EXPECT_TRUE((*sink)->launched());
    const Status closed = (*sink)->close();
    ::setenv("PATH", path.c_str(), 1);
    ASSERT_TRUE(written) << written.error().text();
    ASSERT_TRUE(closed) << closed.error().text();
    std::string ran;
    std::ifstream(marker) >> ran;
    EXPECT_EQ(ran, "with-the-first-frame");
    EXPECT_EQ(fs::file_size(dir / "out.mp4"), 16u) << "the frame's bytes went to the stand-in";
    fs::remove_all(dir);
}

TEST(VideoSink, AMissingFfmpegFailsTheSinkAtOnce) {
    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    ::setenv("PATH", "/nonexistent-toyhost-bin", 1);
    Result<std::unique_ptr<VideoSink>> sink =
        VideoSink::start(std::filesystem::temp_directory_path() / "toyhost-never.mp4", 2, 2, 30.0, {});
    ::setenv("PATH", path.c_str(), 1);
    ASSERT_FALSE(sink);
    EXPECT_NE(sink.error().text().find("ffmpeg: program not found in PATH"), std::string::npos) << sink.error().text();
}
