// FrameRecorder: takes the frames a run captures from the Player to their output (capture/),
// through the FrameStream every render into memory uses (which frames, reads in flight, handed
// over as soon as read). Asynchronous by default: readbacks go through a ReadbackRing (no stall on
// the render thread) and are encoded by an EncoderPool into the sink `--out` asks for (image
// files, ffmpeg video, raw stdout). The synchronous path (read and encode on the render thread) is
// kept for comparison. Needs the player's GL context current for its whole life.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "capture/EncoderPool.h"
#include "capture/FrameStream.h"
#include "capture/OutputPattern.h"
#include "capture/VideoSink.h"
#include "core/Defaults.h"
#include "core/Result.h"
#include "image/ImageStats.h"
#include "manifest/ManifestDesc.h"
#include "player/Player.h"
#include "session/SessionOptions.h"
#include "render/ReadbackRing.h"

namespace toyhost {

struct RecorderSettings {
    OutputPattern output;
    PassId pass = PassId::Image;
    int frames = 0;        // the run's frames (0: no end) and its capture-every (FrameStream's rule)
    int captureEvery = 1;
    bool synchronous = false;      // glReadPixels and encoding on the render thread
    int pngLevel = defaults::kPngLevel;
    ExrSettings exr;
    int encoderThreads = 0;        // 0: defaultEncoderThreads()
    std::size_t memoryCapBytes = defaults::kCaptureMemoryMiB << 20;
    VideoSettings video;
    double fps = defaults::kFps;   // the video's frame rate
    int rawStreamFd = 1;           // where "--out -" writes (stdout)
    // Real-time window runs: when the encoders are behind by the memory cap, drop the frame
    // instead of making the render (UI) thread wait. Off: every frame is written (back-pressure).
    bool dropWhenBusy = false;
    // Published while the render thread waits for the encoders (a stalled ffmpeg shows here).
    RunActivity* activity = nullptr;
    // Asked while the render thread waits for the encoders: a stop ends the wait at once (a
    // PNG at --png-level 9 of a large frame takes seconds), so only the frames being encoded
    // are finished and the stop is not taken for a stuck render.
    std::function<bool()> stopRequested;
};

// The recorder settings a run asks for: its output, pass, PNG level, encoders, memory cap, video
// settings and frame rate (the default rate when a window runs in real time, which then also
// drops frames rather than wait for the encoders).
RecorderSettings recorderSettings(const SessionPlan& run, RunActivity* activity = nullptr,
                                  std::function<bool()> stopRequested = {});

class FrameRecorder {
public:
    // Creates the sink (starting ffmpeg for a video), the encoder threads and the readback ring,
    // sized for the player's current canvas.
    static Result<std::unique_ptr<FrameRecorder>> create(const RecorderSettings& settings, const Player& player);

    // Whether frame `frame` is one the run captures (the capture-every rule).
    bool captures(int frame) const { return stream_->captures(frame); }
    // After the player rendered frame `frame` (every frame, captured or not): captures it when it
    // is one to capture, and hands readbacks that have completed to the encoders without waiting.
    Status rendered(const Player& player, int frame);
    // Waits for every readback and every encoder, then completes the output. Without a
    // successful finish(), destruction discards incomplete output.
    Status finish();

    std::uint64_t bytesWritten() const { return pool_->bytesWritten(); }
    // Stops without completing (an interrupted run): frames read back or queued but not written
    // are dropped, a stream's output is discarded, complete image files stay.
    struct Abandoned {
        int written = 0;  // frames the sink completed
        int dropped = 0;  // captured frames that were never written
    };
    Abandoned abandon();
    int encoderThreads() const { return pool_->threads(); }
    // Frames that were not recorded because the encoders were behind (dropWhenBusy), by number.
    const std::vector<int>& droppedFrames() const { return droppedFrames_; }
    // Float captures (EXR of a buffer, or of Image): the first captured frame that held NaN or Inf,
    // found by scanning what was read back anyway.
    const std::optional<std::pair<int, NonFiniteFind>>& firstNonFinite() const { return firstNonFinite_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Where capture time went, in seconds: on the render thread, reading frames back and waiting
    // for the encoders (back-pressure); on the encoder threads (summed), encoding and writing.
    double readbackSeconds() const { return readbackSeconds_; }
    double waitSeconds() const { return waitSeconds_; }
    double encodeSeconds() const { return sink_->encodeSeconds(); }
    // A video's ffmpeg encoder ("" for image files and raw frames), and with --codec auto why.
    const std::string& videoEncoder() const { return videoEncoder_; }
    const std::string& videoEncoderChoice() const { return videoEncoderChoice_; }
    double writeSeconds() const { return sink_->writeSeconds(); }

    ~FrameRecorder();

private:
    class Reads;
    // Starts capturing the frame the player has just rendered (its iFrame is `frame`).
    Status capture(const Player& player, int frame);
    // Cube A's six faces as one strip, read synchronously (a rare capture: no readback ring).
    Status captureCube(const Player& player, int frame);
    std::vector<float> cubeFace_;

    FrameRecorder() = default;
    Status collectOldest();
    void scanFloatFrame(int frame, const std::vector<std::byte>& pixels);

    std::shared_ptr<GlContext> context_;  // declared first: outlives the readback buffers
    RecorderSettings settings_;
    int width_ = 0, height_ = 0;
    std::vector<int> droppedFrames_;
    Status dropped(int frame);
    int captured_ = 0;  // capture() calls that took a frame
    std::string videoEncoder_, videoEncoderChoice_;
    double readbackSeconds_ = 0;
    double waitSeconds_ = 0;
    std::optional<std::pair<int, NonFiniteFind>> firstNonFinite_;
    // A pixel buffer for a frame: waits for one, or (dropWhenBusy) gives nothing when none is free.
    Result<std::optional<std::vector<std::byte>>> takeBuffer(std::size_t bytes);
    PixelFormat format_ = PixelFormat::Rgba8;
    std::unique_ptr<FrameSink> sink_;    // declared before pool_: the pool's threads use it
    std::unique_ptr<EncoderPool> pool_;
    std::optional<ReadbackRing> ring_;
    std::optional<FrameStream> stream_;
    std::unique_ptr<Reads> reads_;  // the ring (or the synchronous reads) as the stream drives it
};

}  // namespace toyhost
