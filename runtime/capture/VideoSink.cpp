#include "capture/VideoSink.h"
#include "capture/VideoEncoderChoice.h"

#include <atomic>
#include <unistd.h>

#include "core/InFlight.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <sys/stat.h>

#include "capture/FrameBytes.h"
#include "core/AtomicFile.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

std::string formatNumber(double value) {
    std::ostringstream text;
    text.precision(10);
    text << value;
    return text.str();
}

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

// The last lines ffmpeg printed, which name the problem ("Unknown encoder", "No space left").
std::string logTail(const fs::path& log) {
    Result<std::string> text = readTextFile(log);
    if (!text || text->empty()) return {};
    std::string tail = *text;
    while (!tail.empty() && (tail.back() == '\n' || tail.back() == '\r')) tail.pop_back();
    if (tail.size() > 1500) tail = "..." + tail.substr(tail.size() - 1500);
    // One diagnostic is one line.
    std::string joined;
    for (char c : tail) {
        if (c == '\r') continue;
        if (c == '\n') joined += " | ";
        else joined += c;
    }
    return joined;
}

}  // namespace

std::vector<std::string> ffmpegArguments(const VideoRequest& r) {
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-nostats", "-loglevel", "error", "-y",
                                     "-f", "rawvideo", "-pix_fmt", "rgba",
                                     "-video_size", std::to_string(r.width) + "x" + std::to_string(r.height),
                                     "-framerate", formatNumber(r.fps), "-i", "pipe:0"};
    const bool webm = r.container == ".webm";
    const std::string defaultCodec = webm ? "libvpx-vp9" : "libx264";
    const std::string codec = r.settings.codec.value_or(defaultCodec);
    if (codec == "h264_vaapi") args.insert(args.begin() + 6, {"-vaapi_device", "/dev/dri/renderD128"});
    if (r.settings.audio) {
        args.insert(args.end(), {"-i", "file:" + r.settings.audio->string(), "-map", "0:v:0", "-map", "1:a:0", "-c:a",
                                 webm ? "libopus" : "aac", "-b:a", "192k"});
    } else {
        args.push_back("-an");
    }
    args.insert(args.end(), {"-c:v", codec});
    if (codec == "libx264") {
        const bool even = r.width % 2 == 0 && r.height % 2 == 0;
        args.insert(args.end(), {"-preset", r.settings.preset.value_or("medium"), "-crf", std::to_string(r.settings.quality.value_or(18)),
                                 "-pix_fmt", even ? "yuv420p" : "yuv444p"});
    } else if (codec == "libvpx-vp9") {
        // VP9's "good" deadline at cpu-used 4 encodes several times faster than the default with
        // little loss; -b:v 0 makes -crf a pure quality target.
        args.insert(args.end(), {"-crf", std::to_string(r.settings.quality.value_or(31)), "-b:v", "0",
                                 "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-pix_fmt", "yuv420p"});
    } else {
        // Hardware encoders take 4:2:0 frames (VAAPI uploaded to the device); their quality
        // option is not -crf, so --video-quality goes only where it was asked.
        if (codec == "h264_vaapi") args.insert(args.end(), {"-vf", "vflip,format=nv12,hwupload"});
        else if (codec == "h264_qsv") args.insert(args.end(), {"-pix_fmt", "nv12"});
        else if (codec == "h264_nvenc") args.insert(args.end(), {"-pix_fmt", "yuv420p"});
        if (r.settings.preset) args.insert(args.end(), {"-preset", *r.settings.preset});
        if (r.settings.quality) args.insert(args.end(), {"-crf", std::to_string(*r.settings.quality)});
    }
    // Frames go down the pipe as GL reads them, bottom row first; ffmpeg's vflip turns them by
    // stepping its row pointer backwards, so toyhost makes no flipped copy of each frame.
    if (codec != "h264_vaapi") args.insert(args.end(), {"-vf", "vflip"});
    // The same frames give the same bytes: no random Matroska UIDs, no version strings.
    args.insert(args.end(), {"-fflags", "+bitexact", "-flags:v", "+bitexact"});
    // The output is a temporary name without the real extension, so the container is explicit.
    if (r.container == ".mp4") args.insert(args.end(), {"-movflags", "+faststart", "-f", "mp4"});
    else if (r.container == ".mov") args.insert(args.end(), {"-f", "mov"});
    else if (r.container == ".mkv") args.insert(args.end(), {"-f", "matroska"});
    else args.insert(args.end(), {"-f", "webm"});
    args.push_back(r.output.string());
    return args;
}

Result<std::unique_ptr<VideoSink>> VideoSink::start(const fs::path& path, int width, int height, double fps,
                                                    const VideoSettings& settings) {
    std::unique_ptr<VideoSink> sink(new VideoSink());
    sink->path_ = path;
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return fileError(path.parent_path().string(), "cannot create folder: " + ec.message(), Code::IoWrite);
    }
    sink->temp_ = temporarySibling(path);
    // ffmpeg's log goes to the temporary folder, not beside the video: when the output's disk is
    // full, the log must still say so.
    static std::atomic<unsigned> logs{0};
    sink->log_ = fs::temp_directory_path(ec) /
                 ("toyhost-ffmpeg-" + std::to_string(::getpid()) + "-" + std::to_string(logs++) + ".log");
    // Both are removed by an emergency exit (core/InFlight.h); ffmpeg is killed first.
    if (!inflight::addFile(sink->temp_) || !inflight::addFile(sink->log_))
        return fileError(path.string(), "not started: toyhost is stopping", Code::Interrupted);
    sink->registered_ = true;
    VideoRequest request{sink->temp_, lowerExtension(path), width, height, fps, settings};
    if (settings.codec == "auto") {
        // A throughput preset for the software fallback: capture is about keeping up.
        const VideoEncoderChoice choice = chooseAutoVideoEncoder(request.container);
        request.settings.codec = choice.codec;
        if (!choice.hardware && choice.codec == "libx264" && !settings.preset) request.settings.preset = "veryfast";
        sink->autoExplanation_ = choice.explanation() +
                                 (request.settings.preset ? ", preset " + *request.settings.preset : std::string());
    }
    sink->encoder_ = request.settings.codec.value_or(request.container == ".webm" ? "libvpx-vp9" : "libx264");
    sink->arguments_ = ffmpegArguments(request);
    // A missing ffmpeg fails the recording now, as the spawn would (a PATH lookup, no child).
    if (!findExecutable(sink->arguments_.front()))
        return inFile(path.string(), Error(sink->arguments_.front() + ": program not found in PATH", Code::Process));
    return sink;
}

bool VideoSink::launched() const {
    std::lock_guard lock(launchMutex_);
    return ffmpeg_.has_value();
}

Status VideoSink::launch() {
    std::lock_guard lock(launchMutex_);
    if (ffmpeg_) return okStatus();
    if (cancelled_) return fileError(path_.string(), "not started: the recording was cancelled", Code::Interrupted);
    Result<ChildProcess> ffmpeg = ChildProcess::spawn(arguments_, log_);
    if (!ffmpeg) return inFile(path_.string(), ffmpeg.error());
    ffmpeg_.emplace(std::move(*ffmpeg));
    return okStatus();
}

VideoSink::~VideoSink() {
    if (!closed_) discard();
    if (registered_) {
        inflight::removeFile(temp_);
        inflight::removeFile(log_);
    }
}

Error VideoSink::ffmpegFailed(const std::string& what) const {
    std::string message = what;
    if (std::string tail = logTail(log_); !tail.empty()) message += "; ffmpeg said: " + tail;
    return fileError(path_.string(), message,
                     message.find("No space left") != std::string::npos ? Code::IoNoSpace : Code::CaptureFfmpeg);
}

Status VideoSink::write(const CapturedFrame& frame, EncodeScratch& scratch) {
    if (Status launched = launch(); !launched) return launched;
    Clock::time_point at = Clock::now();
    const std::span<const std::uint8_t> bottomUp = rgba8BottomUp(frame, scratch.bytes);
    at = addEncodeTime(at);
    // Writing into ffmpeg's pipe waits while ffmpeg encodes: this is where a video's encoding shows.
    Status written = ffmpeg_->write(std::as_bytes(bottomUp), &writeCancel_);
    addWriteTime(at);
    // Cancelled: discard() kills ffmpeg and what it started; waiting for it here could be forever.
    if (!written && writeCancel_.cancelled()) return fileError(path_.string(), "the recording was cancelled", Code::Interrupted);
    if (!written) {
        // ffmpeg stopped reading: it failed; wait for it so its log is complete.
        (void)ffmpeg_->closeAndWait();
        return ffmpegFailed("ffmpeg stopped reading frames");
    }
    // The encoded file's size so far, for the progress line (a stat, cheap beside encoding).
    struct stat info {};
    if (::stat(temp_.c_str(), &info) == 0) {
        const std::uint64_t size = static_cast<std::uint64_t>(info.st_size);
        const std::uint64_t before = bytesWritten();
        if (size > before) addBytesWritten(size - before);
    }
    return okStatus();
}

Status VideoSink::close() {
    if (Status launched = launch(); !launched) return launched;
    Result<int> exit = ffmpeg_->closeAndWait();
    if (!exit) return ffmpegFailed(exit.error().first().message);
    if (*exit != 0) return ffmpegFailed("ffmpeg failed (exit code " + std::to_string(*exit) + ")");
    // ffmpeg logs only errors here, and a few (writing the trailer on a full disk, with webm and
    // mkv) still end with exit code 0 and a truncated file: any error line fails the video.
    if (!logTail(log_).empty()) return ffmpegFailed("ffmpeg reported an error while finishing the video");
    std::error_code ec;
    fs::rename(temp_, path_, ec);
    if (ec) return fileError(path_.string(), "cannot rename the finished video into place: " + ec.message(), Code::IoWrite);
    closed_ = true;
    const std::uintmax_t size = fs::file_size(path_, ec);
    if (!ec && size > bytesWritten()) addBytesWritten(size - bytesWritten());
    fs::remove(log_, ec);
    return okStatus();
}

void VideoSink::cancel() {
    std::lock_guard lock(launchMutex_);
    cancelled_ = true;
    writeCancel_.cancel();
    if (ffmpeg_) ffmpeg_->killFromAnyThread();
}

void VideoSink::discard() {
    {
        std::lock_guard lock(launchMutex_);
        cancelled_ = true;
    }
    if (ffmpeg_) ffmpeg_->kill();
    std::error_code ec;
    fs::remove(temp_, ec);
    fs::remove(log_, ec);
    closed_ = true;
}

}  // namespace toyhost
