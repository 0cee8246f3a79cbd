// FrameRecorder: the CPU readback adapter of session/FrameConsumer.h: takes the frames a run
// captures from their rendered textures to their output (capture/), through the FrameStream every
// render into memory uses (which frames, reads in flight, handed over as soon as read).
// Asynchronous by default: readbacks go through a ReadbackRing (no stall on the render thread) and
// are encoded by an EncoderPool into the sink `--out` asks for (capture/OutputSink.h). The
// synchronous path (read and encode on the render thread) is kept for comparison. Needs the
// player's GL context current for its whole life.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "capture/EncoderPool.h"
#include "capture/FrameStream.h"
#include "capture/OutputSink.h"
#include "core/Defaults.h"
#include "core/Result.h"
#include "image/ImageStats.h"
#include "manifest/ManifestDesc.h"
#include "player/Player.h"
#include "render/ReadbackRing.h"
#include "session/FrameConsumer.h"
#include "session/SessionOptions.h"

namespace toyhost {

struct RecorderSettings {
    OutputSinkRequest sink;  // its size is the canvas's, set by FrameRecorder::create
    PassId pass = PassId::Image;
    int frames = 0;        // the run's frames (0: no end) and its capture-every (FrameStream's rule)
    int captureEvery = 1;
    bool synchronous = false;      // glReadPixels and encoding on the render thread
    int encoderThreads = 0;        // 0: defaultEncoderThreads()
    std::size_t memoryCapBytes = defaults::kCaptureMemoryMiB << 20;
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

class FrameRecorder final : public FrameConsumer {
public:
    // Creates the sink (a video's command line), the encoder threads and the readback ring, sized
    // for the player's current canvas.
    static Result<std::unique_ptr<FrameRecorder>> create(const RecorderSettings& settings, const Player& player);

    bool captures(int frame) const override { return stream_->captures(frame); }
    // Starts the read of a captured frame (the ring's, or a synchronous one) and hands readbacks
    // that have completed to the encoders without waiting.
    Status rendered(const RenderedFrame& frame) override;
    // Waits for every readback and every encoder, then completes the output.
    Status finish() override;
    Abandoned abandon() override;
    std::uint64_t bytesWritten() const override { return pool_->bytesWritten(); }
    // Where capture time went: on the render thread, reading frames back and waiting for the
    // encoders (back-pressure); on the encoder threads (summed), encoding and writing. Float
    // captures (EXR of a buffer, or of Image) are scanned for NaN and Inf as they are read back.
    ConsumedFrames consumed() const override;
    // With --codec auto, the line saying which video encoder was chosen and why ("" otherwise).
    const std::string& videoEncoderChoice() const { return videoEncoderChoice_; }

    ~FrameRecorder() override;

private:
    class Reads;
    // Starts capturing the frame just rendered.
    Status capture(const RenderedFrame& frame);
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
