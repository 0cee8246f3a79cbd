// VideoSource: the frames of a `video` channel (a movie file, looping) or a `webcam` channel (a V4L2
// camera, newest frame), decoded by an ffmpeg child process that writes raw RGBA frames to a pipe,
// read synchronously (media/VideoStream.h runs one on its own thread, decoding ahead); and the
// deterministic moving stand-in used when no video is available. No GL needed.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/ChildProcess.h"
#include "core/Result.h"
#include "core/TemporaryFiles.h"
#include "image/Image.h"

namespace toyhost {

// What ffprobe reports about a video file's first video stream.
struct VideoInfo {
    int width = 0;   // as shown: rotation metadata applied (ffmpeg and browsers both rotate)
    int height = 0;
    double fps = 0;  // average frame rate (the nominal rate where the container has no average)
    std::int64_t frameCount = 0;  // frames in one pass through the file; 0 for a live camera
};

// Shadertoy facts reproduced here (effect.js EffectPass.NewTexture / Paint_Image and piLibs.js
// UpdateTextureFromImage, as mirrored in public repositories):
// - A `video` input is an HTML <video> with loop = true. While it plays, every rendered frame
//   uploads the video's current frame (UNPACK_FLIP_Y_WEBGL = the channel's vflip, "true" in every
//   export seen, which is our rows-bottom-first Image8 uploaded as it is) and iChannelTime is
//   video.currentTime, so it wraps to 0 at each loop. iChannelResolution is the video's size.
// - The site plays the video in real time; toyhost runs at a fixed time step, so the frame shown
//   at iTime t is the file's frame at t modulo its duration (frameIndexAt): a shard or a resumed
//   run that starts at any t shows the same frames as a run from 0.
// - A `webcam` input shows the camera's newest frame; its iChannelTime is never set (0).
// Checked by tests/io/test_video_source.cpp.
class VideoSource {
public:
    // Probes `path` with ffprobe, starts ffmpeg and decodes frame 0. Errors name the file: not
    // found, not a video (no video stream, a still image), ffmpeg/ffprobe not installed, or
    // ffmpeg's own reason when it cannot decode the file.
    static Result<std::unique_ptr<VideoSource>> openFile(const std::filesystem::path& path);
    // A V4L2 camera (`/dev/video0`) through `ffmpeg -f v4l2`: live, frameAt() gives the newest
    // frame whatever the time. Waits for the first frame (up to 10 seconds).
    static Result<std::unique_ptr<VideoSource>> openDevice(const std::string& device);

    // Kills and reaps the ffmpeg child and removes its log.
    ~VideoSource();
    VideoSource(const VideoSource&) = delete;
    VideoSource& operator=(const VideoSource&) = delete;

    int width() const { return info_.width; }
    int height() const { return info_.height; }
    double fps() const { return info_.fps; }
    std::int64_t frameCount() const { return info_.frameCount; }
    bool live() const { return live_; }
    // The loop length in seconds: frameCount() / fps(); 0 for a camera.
    double duration() const;
    const VideoInfo& info() const { return info_; }

    // The frame shown at iTime `seconds`: floor(seconds * fps) modulo frameCount() (0 for a camera).
    std::int64_t frameIndexAt(double seconds) const;
    // iChannelTime at iTime `seconds`: the playback position, wrapping at duration(); 0 for a camera.
    double playbackTime(double seconds) const;

    // The frame shown at iTime `seconds`, RGBA8 rows bottom first, width() x height(). Reading
    // forward is sequential and allocates nothing; a jump backwards or far ahead restarts ffmpeg
    // at that frame (-ss), and the loop from the last frame back to the first continues in the
    // same process (-stream_loop) once it started at frame 0. For a camera: the newest frame that
    // has arrived. On an error (ffmpeg died, the file was truncated) frame() keeps the last good
    // frame and the error names the file and ffmpeg's reason. The pointer is never null on success
    // and stays valid until the next call.
    Result<const Image8*> frameAt(double seconds);
    // The same by frame index (0 .. frameCount() - 1; files only).
    Result<const Image8*> frameByIndex(std::int64_t index);
    // For a camera: waits (up to 30 s) for the next frame it sends and returns it.
    Result<const Image8*> nextCameraFrame();
    // The frame the last frameAt() returned (frame 0 right after openFile).
    const Image8& frame() const { return frame_; }
    // Swaps the pixels of frame() with `rgba` (which must hold width() * height() * 4 bytes), so a
    // reader on another thread takes the frame without a copy; frame() then holds no frame.
    void exchangeFrame(std::vector<std::uint8_t>& rgba);

    // Kills the decoder from any thread, so that a read waiting for it returns at once, and starts
    // no other: every later read is an error. For the owner of a decoding thread, before joining it.
    void interrupt();

    // Decoder processes started so far (1 after open); for tests and the cost measurements.
    int decoderStarts() const { return starts_; }

private:
    VideoSource() = default;

    Status startDecoder(std::int64_t firstFrame);
    void dropDecoder();  // kills and reaps the decoder (under decoderMutex_)
    Status readNextFrame();
    Result<const Image8*> newestCameraFrame();
    Error decoderFailed(const std::string& what) const;
    // After the end of the decoder's output: waits for it (killing it after 5 s) and says how it
    // ended: "" for exit code 0, else "exit code N" or the signal that ended it.
    std::string decoderEnded();

    std::filesystem::path path_;  // the file, or the device
    std::unique_ptr<TemporaryFiles> log_;  // ffmpeg's stderr (declared before the decoder: outlives it)
    VideoInfo info_;
    bool live_ = false;
    std::mutex decoderMutex_;  // guards decoder_'s replacement against interrupt() from another thread
    bool interrupted_ = false;
    std::optional<ChildProcess> decoder_;  // ffmpeg writing raw RGBA frames to a pipe
    bool looping_ = false;         // the decoder started at frame 0 with -stream_loop
    std::int64_t current_ = -1;    // the index of frame_'s content
    std::int64_t next_ = 0;        // the index the decoder delivers next
    Image8 frame_;
    std::vector<std::uint8_t> spare_;  // the next frame is read here, then swapped into frame_
    std::atomic<int> starts_{0};  // read by other threads (VideoStream::decoderStarts)
};

// The stand-in for a `video` or `webcam` channel whose source is not available: 640x360
// (defaults::kVideoStandInWidth/Height), looping every 10 seconds, scrolling colour bars over the
// top three quarters, a grey ramp scrolling the other way along the bottom quarter (so a flipped
// upload is obvious) and a disc moving along a closed path. The same bytes on every run and machine (integer arithmetic on the time rounded to
// 1/600 s). Reuses `out`'s buffer: after the first call a frame costs no allocation.
inline constexpr double kVideoStandInDuration = 10.0;
void videoStandInFrame(double seconds, Image8& out);
// iChannelTime for the stand-in at iTime `seconds` (wraps every kVideoStandInDuration).
double videoStandInPlaybackTime(double seconds);

}  // namespace toyhost
