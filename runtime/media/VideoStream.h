// VideoStream: the frames of a `video` or `webcam` channel, decoded on their own thread so that the
// render thread never reads a pipe. A file is decoded ahead, in order, into a small queue of frames
// that each carry their index (bounded: defaults::kVideoAheadFrames frames, kVideoAheadBytes), so
// the frame shown for index i is always the file's frame i, whatever the timing: headless runs stay
// deterministic. A camera's newest frame is kept. Opening (ffprobe, the first frame) happens in
// open*, which the plan calls off the GL thread (media/ChannelMedia.h). No GL needed.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/Result.h"
#include "core/RunActivity.h"
#include "image/Image.h"
#include "media/VideoSource.h"

namespace toyhost {

// Who waits when the decoder is behind, published for a watchdog (RunActivity::WaitingForInput).
struct InputWait {
    RunActivity* activity = nullptr;  // nothing is published when null
    const char* pass = "";            // a string that lives for the whole run (passName())
    int frame = -1;                   // iFrame
};

class VideoStream {
public:
    // A video file: probed, frame 0 decoded (errors as VideoSource::openFile), then decoded ahead.
    static Result<std::shared_ptr<VideoStream>> openFile(const std::filesystem::path& path);
    // A V4L2 camera: its first frame waited for (as VideoSource::openDevice), then read as it comes.
    static Result<std::shared_ptr<VideoStream>> openDevice(const std::string& device);
    // Stops the thread and the decoder (killed and reaped).
    ~VideoStream();
    VideoStream(const VideoStream&) = delete;
    VideoStream& operator=(const VideoStream&) = delete;

    const VideoInfo& info() const { return info_; }
    int width() const { return info_.width; }
    int height() const { return info_.height; }
    bool live() const { return live_; }
    // As VideoSource: the frame index shown at iTime `seconds` (0 for a camera), and iChannelTime.
    std::int64_t frameIndexAt(double seconds) const;
    double playbackTime(double seconds) const;

    // File: frame `index` (0 .. frameCount - 1). Returns at once when the decoder has it queued;
    // frames queued before it are dropped. When the decoder has not reached it yet, waits for it
    // (publishing `wait`); a frame behind the queue or far ahead of it repositions the decoder
    // (which restarts ffmpeg there when reading forward would take longer). Camera: the newest
    // frame that has arrived, never waiting. On an error (ffmpeg died, the file was truncated) the
    // error names the file, and frame() keeps the last good frame; the next call starts again.
    // The pointer stays valid until the next call. Allocates nothing once running.
    Result<const Image8*> frame(std::int64_t index, const InputWait& wait = {});
    // The frame the last frame() returned (frame 0 right after opening).
    const Image8& current() const { return shown_; }
    // Changes whenever current() shows another frame.
    std::uint64_t currentVersion() const { return shownVersion_; }

    // Blocks until the decoder has filled the queue ahead of the frame shown (or failed, or has
    // nothing to do: a camera). For a driver that wants the first frames ready before it starts
    // its clock, and for tests.
    void waitUntilQueued() const;

    // For tests and measurements: how many times frame() had to wait for the decoder, and how
    // many ffmpeg processes were started.
    std::uint64_t waits() const;
    int decoderStarts() const;
    // The most frames held ahead of the one shown.
    int queueCapacity() const { return static_cast<int>(ring_.size()); }

private:
    explicit VideoStream(std::unique_ptr<VideoSource> source);
    void decodeFiles();    // the thread of a file
    void readCamera();     // the thread of a camera
    std::int64_t forward(std::int64_t from, std::int64_t to) const;  // frames from `from` to `to`, looping
    void reposition(std::int64_t index);  // under mutex_

    struct Entry {
        std::int64_t index = -1;
        std::vector<std::uint8_t> rgba;
    };

    std::unique_ptr<VideoSource> source_;  // used by the thread only, once it runs
    VideoInfo info_;
    bool live_ = false;
    std::int64_t maxSkip_ = 0;  // a frame further ahead than this repositions the decoder
    std::size_t frameBytes_ = 0;

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;  // the queue, a request or an error changed
    std::vector<Entry> ring_;          // capacity fixed at open
    std::size_t head_ = 0;
    std::size_t count_ = 0;
    std::int64_t decodeNext_ = 0;      // the index the decoder queues next
    std::uint64_t generation_ = 0;     // changes at every reposition: frames of an older one are dropped
    std::optional<Error> error_;       // the decoder failed; it waits for a reposition
    bool errorReported_ = false;       // frame() returned error_ once; the next request repositions
    bool stop_ = false;
    std::uint64_t waits_ = 0;
    std::vector<std::uint8_t> newest_;  // camera: the newest frame, and its number
    std::uint64_t newestVersion_ = 0;

    Image8 shown_;                     // render thread only
    std::int64_t shownIndex_ = -1;
    std::uint64_t shownVersion_ = 0;
    std::uint64_t takenCameraVersion_ = 0;

    std::thread thread_;  // last: started when everything above exists
};

}  // namespace toyhost
