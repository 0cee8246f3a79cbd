#include "media/VideoSource.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <optional>
#include <poll.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"

namespace toyhost {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// How long a read waits for ffmpeg before giving up on it (a stalled decoder or camera).
constexpr int kFrameTimeoutMs = 30000;
constexpr int kFirstCameraFrameTimeoutMs = 10000;

// What ffprobe or ffmpeg printed, as one line (one diagnostic is one line): blank lines and the
// empty JSON document ffprobe prints on failure dropped, the input's name ("file:/x/y.txt: ...")
// and the "[mov,mp4,... @ 0x55...] " context prefixes removed (the diagnostic names the file; an
// address differs on every run), the last ~1200 characters kept.
std::string toolMessage(const std::string& text, const std::string& input) {
    std::string joined;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        start = end + 1;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
        for (std::size_t at = line.find(input + ": "); at != std::string::npos; at = line.find(input + ": "))
            line.erase(at, input.size() + 2);
        if (line.starts_with("[")) {
            const std::size_t close = line.find("] ");
            if (close != std::string::npos && line.find(" @ 0x") < close) line.erase(0, close + 2);
        }
        if (line.empty() || line == "{" || line == "}") continue;
        joined += (joined.empty() ? "" : " | ") + line;
    }
    if (joined.size() > 1200) joined = "..." + joined.substr(joined.size() - 1200);
    return joined;
}

// "30000/1001" -> 29.97; 0 for "0/0" or anything unreadable.
double parseRate(const json& value) {
    if (!value.is_string()) return 0;
    const std::string text = value.get<std::string>();
    long long num = 0, den = 0;
    if (std::sscanf(text.c_str(), "%lld/%lld", &num, &den) != 2 || num <= 0 || den <= 0) return 0;
    return static_cast<double>(num) / static_cast<double>(den);
}

// ffprobe writes numbers as strings ("120", "4.000000"); missing or "N/A" gives `fallback`.
double parseNumber(const json& object, const char* key, double fallback = 0) {
    if (!object.is_object() || !object.contains(key)) return fallback;
    const json& value = object[key];
    if (value.is_number()) return value.get<double>();
    if (!value.is_string()) return fallback;
    char* end = nullptr;
    const std::string text = value.get<std::string>();
    const double parsed = std::strtod(text.c_str(), &end);
    return (end != text.c_str() && std::isfinite(parsed)) ? parsed : fallback;
}

// The clockwise rotation (0, 90, 180, 270) a player applies: the display matrix side data or the
// older "rotate" tag.
int displayRotation(const json& stream) {
    double degrees = 0;
    if (stream.contains("side_data_list") && stream["side_data_list"].is_array())
        for (const json& side : stream["side_data_list"])
            if (side.is_object() && side.contains("rotation")) degrees = parseNumber(side, "rotation");
    if (degrees == 0 && stream.contains("tags")) degrees = parseNumber(stream["tags"], "rotate");
    const long quarter = std::lround(degrees / 90.0);
    return static_cast<int>(((quarter % 4) + 4) % 4) * 90;
}

// Runs ffprobe with `arguments` (after "ffprobe") and parses its JSON. Errors name `file`.
Result<json> runFfprobe(const std::vector<std::string>& arguments, const std::string& file, const std::string& input) {
    if (!findExecutable("ffprobe"))
        return fileError(file, "cannot read video: ffprobe (part of ffmpeg) is not installed", Code::VideoNoFfmpeg);
    TemporaryFiles temp("ffprobe", {"log"});
    if (!temp.registerAll()) return fileError(file, "not started: toyhost is stopping", Code::Interrupted);
    const fs::path& log = temp[0];
    std::vector<std::string> argv = {"ffprobe"};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    // ffprobe's JSON and its error lines both go to the log: a clean run prints only the JSON.
    Result<ChildProcess> probe = ChildProcess::spawn(argv, log);
    Result<int> exit = probe ? probe->closeAndWait() : Result<int>(probe.error());
    Result<std::string> output = readTextFile(log);
    if (!exit) return inFile(file, exit.error());
    if (*exit != 0) {
        // The log holds ffprobe's error lines around the empty JSON document it still prints.
        const std::string reason = output ? toolMessage(*output, input) : std::string();
        return fileError(file, "cannot read as a video: " + (reason.empty() ? "ffprobe failed" : reason), Code::VideoProbe);
    }
    if (!output) return inFile(file, output.error());
    // Error lines a successful run printed (a damaged packet) come before or after the document.
    const std::size_t open = output->find('{');
    const std::size_t close = output->rfind('}');
    json document = json::value_t::discarded;
    if (open != std::string::npos && close != std::string::npos && close > open)
        document = json::parse(output->substr(open, close - open + 1), nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded() || !document.is_object())
        return fileError(file, "cannot read as a video: ffprobe printed no readable description", Code::VideoProbe);
    return document;
}

// The size, frame rate and frame count of the first video stream of a probed input.
Result<VideoInfo> videoInfoFrom(const json& document, const std::string& file, bool live) {
    static const json kNone;
    const json& streams = document.contains("streams") ? document["streams"] : kNone;
    if (!streams.is_array() || streams.empty() || !streams[0].is_object())
        return fileError(file, live ? "the camera gives no video stream" : "not a video: it has no video stream",
                         Code::VideoNoStream);
    const json& stream = streams[0];
    if (!live && document.contains("format") && document["format"].contains("format_name") &&
        document["format"]["format_name"].is_string()) {
        const std::string format = document["format"]["format_name"].get<std::string>();
        const bool still = format == "image2" || (format.size() > 5 && format.ends_with("_pipe"));
        if (still) return fileError(file, "not a video: it is a still image (bind it as a texture)", Code::VideoStillImage);
    }
    VideoInfo info;
    info.width = static_cast<int>(parseNumber(stream, "width"));
    info.height = static_cast<int>(parseNumber(stream, "height"));
    if (info.width <= 0 || info.height <= 0 || info.width > 16384 || info.height > 16384)
        return fileError(file, "the video stream has no usable size (" + std::to_string(info.width) + "x" +
                                   std::to_string(info.height) + ")", Code::VideoSize);
    if (displayRotation(stream) % 180 == 90) std::swap(info.width, info.height);
    info.fps = parseRate(stream.value("avg_frame_rate", json()));
    if (info.fps <= 0 || info.fps > 1000) info.fps = parseRate(stream.value("r_frame_rate", json()));
    if (info.fps <= 0 || info.fps > 1000) {
        if (!live) return fileError(file, "the video stream has no frame rate", Code::VideoRate);
        info.fps = 30;  // a camera that does not say: the site asks browsers for 30
    }
    if (live) return info;
    // Demuxed packets are the exact count for every common codec (one frame per packet); the
    // container's own count and the duration are fallbacks.
    double count = parseNumber(stream, "nb_read_packets");
    if (count <= 0) count = parseNumber(stream, "nb_frames");
    if (count <= 0) {
        double seconds = parseNumber(stream, "duration");
        if (seconds <= 0 && document.contains("format")) seconds = parseNumber(document["format"], "duration");
        count = std::round(seconds * info.fps);
    }
    if (count < 1) return fileError(file, "not a video: it has no frames", Code::VideoNoFrames);
    info.frameCount = static_cast<std::int64_t>(count);
    return info;
}

std::string formatSeconds(double seconds) {
    char text[64];
    std::snprintf(text, sizeof text, "%.6f", seconds);
    return text;
}

// Reads one frame (height rows of rowBytes, top row first on the pipe) into `rgba` with its rows
// reversed, so the result is bottom row first, without an intermediate copy. True when a whole frame
// was read, false at the end of the stream before its first byte.
Result<bool> readFrameFlipped(int fd, std::uint8_t* rgba, std::size_t rowBytes, int height, int timeoutMs) {
    const std::size_t total = rowBytes * static_cast<std::size_t>(height);
    std::size_t done = 0;
    std::array<iovec, 256> parts;
    while (done < total) {
        pollfd ready{fd, POLLIN, 0};
        const int polled = ::poll(&ready, 1, timeoutMs);
        if (polled < 0) {
            if (errno == EINTR) continue;
            return Error(std::string("poll failed: ") + std::strerror(errno), Code::VideoRead);
        }
        if (polled == 0) return Error("ffmpeg sent no frame for " + std::to_string(timeoutMs / 1000) + " s", Code::VideoRead);
        const std::size_t firstRow = done / rowBytes;
        std::size_t into = done % rowBytes;
        int count = 0;
        for (std::size_t row = firstRow; row < static_cast<std::size_t>(height) && count < int(parts.size()); ++row) {
            std::uint8_t* destination = rgba + (static_cast<std::size_t>(height) - 1 - row) * rowBytes;
            parts[count++] = iovec{destination + into, rowBytes - into};
            into = 0;
        }
        const ssize_t got = ::readv(fd, parts.data(), count);
        if (got < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return Error(std::string("reading ffmpeg's output failed: ") + std::strerror(errno), Code::VideoRead);
        }
        if (got == 0) {
            if (done == 0) return false;
            return Error("ffmpeg's output ended in the middle of a frame", Code::VideoRead);
        }
        done += static_cast<std::size_t>(got);
    }
    return true;
}

}  // namespace

// The decoder (declared after the log) is killed and reaped before its log goes.
VideoSource::~VideoSource() = default;

Result<std::unique_ptr<VideoSource>> VideoSource::openFile(const fs::path& path) {
    const std::string file = path.string();
    if (Status regular = checkRegularFile(path, "video"); !regular) return regular.error();
    // "file:" keeps ffmpeg from reading a name such as "a:b.mp4" or "-x.mp4" as a protocol or option.
    const std::string input = "file:" + file;
    Result<json> probe = runFfprobe({"-hide_banner", "-loglevel", "error", "-select_streams", "v:0", "-count_packets",
                                     "-show_entries",
                                     "stream=width,height,avg_frame_rate,r_frame_rate,nb_frames,nb_read_packets,"
                                     "duration:stream_side_data=rotation:stream_tags=rotate:format=format_name,duration",
                                     "-of", "json", input},
                                    file, input);
    if (!probe) return probe.error();
    Result<VideoInfo> info = videoInfoFrom(*probe, file, false);
    if (!info) return info.error();

    std::unique_ptr<VideoSource> video(new VideoSource());
    video->path_ = path;
    video->info_ = *info;
    video->log_ = std::make_unique<TemporaryFiles>("ffmpeg-video", std::initializer_list<const char*>{"log"});
    if (!video->log_->registerAll()) return fileError(file, "not started: toyhost is stopping", Code::Interrupted);
    const std::size_t bytes = frameBytes(info->width, info->height, PixelFormat::Rgba8);
    video->frame_ = Image8{info->width, info->height, std::vector<std::uint8_t>(bytes)};
    video->spare_.resize(bytes);
    // Decoding frame 0 now reports a file ffprobe can read but ffmpeg cannot decode at open time.
    Result<const Image8*> first = video->frameAt(0.0);
    if (!first) return first.error();
    return video;
}

Result<std::unique_ptr<VideoSource>> VideoSource::openDevice(const std::string& device) {
    struct stat node {};
    if (::stat(device.c_str(), &node) != 0)
        return fileError(device, std::string("camera not found: ") + std::strerror(errno), Code::VideoDevice);
    if (!S_ISCHR(node.st_mode)) return fileError(device, "not a camera device (a V4L2 device such as /dev/video0)", Code::VideoDevice);
    Result<json> probe = runFfprobe({"-hide_banner", "-loglevel", "error", "-f", "v4l2", "-select_streams", "v:0",
                                     "-show_entries", "stream=width,height,avg_frame_rate,r_frame_rate", "-of", "json",
                                     device},
                                    device, device);
    if (!probe) return probe.error();
    Result<VideoInfo> info = videoInfoFrom(*probe, device, true);
    if (!info) return info.error();

    std::unique_ptr<VideoSource> video(new VideoSource());
    video->path_ = device;
    video->info_ = *info;
    video->live_ = true;
    video->log_ = std::make_unique<TemporaryFiles>("ffmpeg-camera", std::initializer_list<const char*>{"log"});
    if (!video->log_->registerAll()) return fileError(device, "not started: toyhost is stopping", Code::Interrupted);
    const std::size_t bytes = frameBytes(info->width, info->height, PixelFormat::Rgba8);
    video->frame_ = Image8{info->width, info->height, std::vector<std::uint8_t>(bytes)};
    video->spare_.resize(bytes);
    if (Status started = video->startDecoder(0); !started) return started.error();
    Result<bool> first = readFrameFlipped(video->decoder_->outputFd(), video->spare_.data(),
                                          static_cast<std::size_t>(info->width) * 4, info->height,
                                          kFirstCameraFrameTimeoutMs);
    if (!first) return video->decoderFailed(first.error().first().message);
    if (!*first) return video->decoderFailed("the camera sent no frame");
    std::swap(video->frame_.rgba, video->spare_);
    video->current_ = 0;
    return video;
}

double VideoSource::duration() const { return live_ ? 0.0 : static_cast<double>(info_.frameCount) / info_.fps; }

std::int64_t VideoSource::frameIndexAt(double seconds) const {
    if (live_ || info_.frameCount <= 0 || !std::isfinite(seconds)) return 0;
    // The epsilon keeps t = k / fps computed in floating point (0.1 * 10 = 0.9999...) on frame k.
    const double frames = std::floor(seconds * info_.fps + 1e-6);
    const double count = static_cast<double>(info_.frameCount);
    double index = std::fmod(frames, count);
    if (index < 0) index += count;
    return static_cast<std::int64_t>(index);
}

double VideoSource::playbackTime(double seconds) const {
    const double length = duration();
    if (length <= 0 || !std::isfinite(seconds)) return 0.0;
    double position = std::fmod(seconds, length);
    if (position < 0) position += length;
    return position;
}

Error VideoSource::decoderFailed(const std::string& what) const {
    std::string message = what;
    const std::string input = live_ ? path_.string() : "file:" + path_.string();
    Result<std::string> log = readTextFile((*log_)[0]);
    if (std::string said = log ? toolMessage(*log, input) : std::string(); !said.empty())
        message += "; ffmpeg said: " + said;
    return fileError(path_.string(), message, Code::VideoDecode);
}

std::string VideoSource::decoderEnded() {
    Result<int> exit = decoder_->closeAndWait(5000);
    if (!exit) return exit.error().first().message;
    return *exit == 0 ? std::string() : "exit code " + std::to_string(*exit);
}

Status VideoSource::startDecoder(std::int64_t firstFrame) {
    dropDecoder();
    std::vector<std::string> argv = {"ffmpeg", "-hide_banner", "-nostdin", "-loglevel", "error"};
    if (live_) {
        argv.insert(argv.end(), {"-f", "v4l2", "-i", path_.string()});
    } else {
        // From frame 0 the file loops inside ffmpeg; started elsewhere it plays to the end and is
        // restarted at 0 (ffmpeg 5's -stream_loop after an -ss seek restarts at the wrong frame).
        if (firstFrame == 0) argv.insert(argv.end(), {"-stream_loop", "-1"});
        // A quarter frame before frame k: accurate seeking then drops frames k-1 and earlier
        // and keeps k whatever the rounding of its timestamp.
        else argv.insert(argv.end(), {"-ss", formatSeconds((static_cast<double>(firstFrame) - 0.25) / info_.fps)});
        argv.insert(argv.end(), {"-i", "file:" + path_.string()});
    }
    // Every decoded frame once (no duplicates or drops for rate conversion), scaled to the probed
    // size so a stream that changes size mid-file cannot break the frame boundaries.
    argv.insert(argv.end(), {"-map", "0:v:0", "-an", "-sn", "-dn", "-fps_mode", "passthrough", "-s",
                             std::to_string(info_.width) + "x" + std::to_string(info_.height), "-pix_fmt", "rgba",
                             "-f", "rawvideo", "pipe:1"});
    // ffmpeg writes raw frames to a pipe read here (stdin /dev/null, stderr the log).
    std::lock_guard lock(decoderMutex_);
    if (interrupted_) return fileError(path_.string(), "the decoder was stopped", Code::Interrupted);
    Result<ChildProcess> started = ChildProcess::spawnReading(argv, (*log_)[0]);
    if (!started) return inFile(path_.string(), started.error());
    decoder_.emplace(std::move(*started));
    // A bigger pipe, fewer wake-ups per frame (a 720p frame is 3.7 MB); best effort.
    (void)::fcntl(decoder_->outputFd(), F_SETPIPE_SZ, 1 << 20);
    ++starts_;
    looping_ = !live_ && firstFrame == 0;
    next_ = firstFrame;
    return okStatus();
}

Status VideoSource::readNextFrame() {
    const std::size_t rowBytes = static_cast<std::size_t>(info_.width) * 4;
    // Two tries: a decoder that reaches the end of a file it does not loop is restarted at frame 0.
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (!decoder_ || (!looping_ && next_ >= info_.frameCount))
            if (Status started = startDecoder(next_ >= info_.frameCount ? 0 : next_); !started) return started;
        Result<bool> read = readFrameFlipped(decoder_->outputFd(), spare_.data(), rowBytes, info_.height, kFrameTimeoutMs);
        if (!read) {
            // A decoder killed or crashed mid-frame ends like one that stopped between frames.
            const std::string why = read.error().first().message;
            const std::string ended = decoderEnded();
            dropDecoder();
            return decoderFailed("ffmpeg stopped decoding at frame " + std::to_string(next_) + " (" + why +
                                 (ended.empty() ? "" : "; " + ended) + ")");
        }
        if (*read) {
            std::swap(frame_.rgba, spare_);
            current_ = next_;
            // A looping decoder wraps; one started with -ss ends after the last frame.
            next_ = looping_ ? (next_ + 1) % info_.frameCount : next_ + 1;
            return okStatus();
        }
        // The end of the stream. A looping decoder never ends by itself, and one that failed or was
        // killed is an error. One that ended cleanly short of the frame count (the count was wrong)
        // continues from the start.
        const std::string ended = decoderEnded();
        dropDecoder();
        if (looping_ || !ended.empty())
            return decoderFailed("ffmpeg stopped decoding at frame " + std::to_string(next_) +
                                 (ended.empty() ? "" : " (" + ended + ")"));
        next_ = info_.frameCount;
    }
    return decoderFailed("ffmpeg gives no frames");
}

Result<const Image8*> VideoSource::newestCameraFrame() {
    if (!decoder_) return decoderFailed("the camera stopped");
    const std::size_t rowBytes = static_cast<std::size_t>(info_.width) * 4;
    // Every frame that has arrived since the last call is read; the newest is shown.
    for (;;) {
        pollfd ready{decoder_->outputFd(), POLLIN, 0};
        const int polled = ::poll(&ready, 1, 0);
        if (polled < 0 && errno == EINTR) continue;
        if (polled <= 0 || !(ready.revents & (POLLIN | POLLHUP))) break;
        Result<bool> read = readFrameFlipped(decoder_->outputFd(), spare_.data(), rowBytes, info_.height, kFrameTimeoutMs);
        if (!read || !*read) {
            Error failed = decoderFailed(read ? std::string("the camera stopped") : read.error().first().message);
            dropDecoder();
            return failed;
        }
        std::swap(frame_.rgba, spare_);
        ++current_;
    }
    return &frame_;
}

void VideoSource::dropDecoder() {
    std::lock_guard lock(decoderMutex_);
    decoder_.reset();
}

void VideoSource::interrupt() {
    std::lock_guard lock(decoderMutex_);
    interrupted_ = true;
    if (decoder_) decoder_->killFromAnyThread();
}

void VideoSource::exchangeFrame(std::vector<std::uint8_t>& rgba) {
    std::swap(frame_.rgba, rgba);
    current_ = -1;  // frame_ no longer holds a decoded frame
}

Result<const Image8*> VideoSource::nextCameraFrame() {
    if (!decoder_) return decoderFailed("the camera stopped");
    const std::size_t rowBytes = static_cast<std::size_t>(info_.width) * 4;
    Result<bool> read = readFrameFlipped(decoder_->outputFd(), spare_.data(), rowBytes, info_.height, kFrameTimeoutMs);
    if (!read || !*read) {
        Error failed = decoderFailed(read ? std::string("the camera stopped") : read.error().first().message);
        dropDecoder();
        return failed;
    }
    std::swap(frame_.rgba, spare_);
    ++current_;
    return &frame_;
}

Result<const Image8*> VideoSource::frameAt(double seconds) {
    if (live_) return newestCameraFrame();
    return frameByIndex(frameIndexAt(seconds));
}

Result<const Image8*> VideoSource::frameByIndex(std::int64_t wanted) {
    if (live_) return newestCameraFrame();
    if (wanted < 0 || wanted >= info_.frameCount) wanted = 0;
    if (wanted == current_) return &frame_;
    const std::int64_t count = info_.frameCount;
    // Frames to read and drop before `wanted`, going forward (through the loop when ffmpeg loops;
    // a decoder started with -ss only reaches frames up to the last).
    const bool reachable = decoder_ && (looping_ || wanted >= next_);
    std::int64_t skip = looping_ ? ((wanted - next_) % count + count) % count : wanted - next_;
    // Decoding ahead costs a few ms a frame; a restart costs ffmpeg's start plus decoding from the
    // previous keyframe (tenths of a second, measured): skip up to about two seconds of video.
    const std::int64_t maxSkip = std::max<std::int64_t>(30, std::llround(2 * info_.fps));
    if (!reachable || skip > maxSkip) {
        if (Status started = startDecoder(wanted); !started) return started.error();
        skip = 0;
    }
    for (std::int64_t i = 0; i <= skip; ++i)
        if (Status read = readNextFrame(); !read) return read.error();
    return &frame_;
}

namespace {

// A triangle wave over `period` ticks: 0 at 0, `span` at period/2, back to 0 at `period`.
std::int64_t triangle(std::int64_t tick, std::int64_t period, std::int64_t span) {
    const std::int64_t phase = tick % period;
    const std::int64_t rising = phase < period / 2 ? 2 * phase : 2 * (period - phase);
    return rising * span / period;
}

}  // namespace

void videoStandInFrame(double seconds, Image8& out) {
    constexpr int kWidth = defaults::kVideoStandInWidth, kHeight = defaults::kVideoStandInHeight;
    constexpr std::int64_t kTicksPerSecond = 600;
    constexpr std::int64_t kPeriod = static_cast<std::int64_t>(kVideoStandInDuration) * kTicksPerSecond;
    std::int64_t tick = std::isfinite(seconds) ? std::llround(seconds * kTicksPerSecond) % kPeriod : 0;
    if (tick < 0) tick += kPeriod;

    out.width = kWidth;
    out.height = kHeight;
    out.rgba.resize(frameBytes(kWidth, kHeight, PixelFormat::Rgba8));  // allocates on the first call only
    const std::size_t rowBytes = static_cast<std::size_t>(kWidth) * 4;
    std::uint8_t* pixels = out.rgba.data();

    // 75% colour bars, 80 px each, scrolling left one frame width per loop.
    static constexpr std::uint8_t kBars[8][3] = {{191, 191, 191}, {191, 191, 0}, {0, 191, 191}, {0, 191, 0},
                                                 {191, 0, 191},   {191, 0, 0},   {0, 0, 191},   {16, 16, 16}};
    const int shift = static_cast<int>(tick * kWidth / kPeriod);
    constexpr int kRampRows = kHeight / 4;  // rows 0 .. kRampRows-1 are the bottom of the picture
    std::uint8_t* barRow = pixels + static_cast<std::size_t>(kHeight - 1) * rowBytes;
    std::uint8_t* rampRow = pixels;
    for (int x = 0; x < kWidth; ++x) {
        const std::uint8_t* bar = kBars[((x + shift) % kWidth) / (kWidth / 8)];
        std::uint8_t* p = barRow + static_cast<std::size_t>(x) * 4;
        p[0] = bar[0], p[1] = bar[1], p[2] = bar[2], p[3] = 255;
        const auto grey = static_cast<std::uint8_t>(((x + kWidth - shift) % kWidth) * 255 / (kWidth - 1));
        std::uint8_t* q = rampRow + static_cast<std::size_t>(x) * 4;
        q[0] = grey, q[1] = grey, q[2] = grey, q[3] = 255;
    }
    for (int y = kRampRows; y < kHeight - 1; ++y) std::memcpy(pixels + y * rowBytes, barRow, rowBytes);
    for (int y = 1; y < kRampRows; ++y) std::memcpy(pixels + y * rowBytes, rampRow, rowBytes);

    // An orange disc with a white rim, bouncing twice across and three times up and down per loop.
    constexpr int kRadius = 36, kRim = 4;
    const int cx = kRadius + static_cast<int>(triangle(tick, kPeriod / 2, kWidth - 2 * kRadius));
    const int cy = kRadius + static_cast<int>(triangle(tick, kPeriod / 3, kHeight - 2 * kRadius));
    // Clipped to the frame: at the ends of its path the disc's edge touches the right or top side,
    // where x = kWidth would wrap into the next row and y = kHeight is past the last one.
    for (int y = std::max(cy - kRadius, 0); y <= std::min(cy + kRadius, kHeight - 1); ++y) {
        for (int x = std::max(cx - kRadius, 0); x <= std::min(cx + kRadius, kWidth - 1); ++x) {
            const int d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
            if (d2 > kRadius * kRadius) continue;
            std::uint8_t* p = pixels + static_cast<std::size_t>(y) * rowBytes + static_cast<std::size_t>(x) * 4;
            const bool rim = d2 > (kRadius - kRim) * (kRadius - kRim);
            p[0] = 255, p[1] = rim ? 255 : 96, p[2] = rim ? 255 : 16, p[3] = 255;
        }
    }
}

double videoStandInPlaybackTime(double seconds) {
    if (!std::isfinite(seconds)) return 0.0;
    double position = std::fmod(seconds, kVideoStandInDuration);
    if (position < 0) position += kVideoStandInDuration;
    return position;
}

}  // namespace toyhost
