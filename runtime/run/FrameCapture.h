// FrameCapture: takes the frames a headless run captures from the renderer to their output.
// Asynchronous by default: readbacks go through a ReadbackRing (no stall on the render thread)
// and are encoded by an EncoderPool into the sink `--out` asks for (image files, ffmpeg video,
// raw stdout). The synchronous path (read and encode on the render thread) is kept for
// comparison. Needs the renderer's GL context current for its whole life.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "capture/EncoderPool.h"
#include "capture/OutputPattern.h"
#include "capture/ReadbackRing.h"
#include "capture/VideoSink.h"
#include "core/Result.h"
#include "manifest/ManifestDesc.h"
#include "render/Renderer.h"

namespace toyhost {

struct CaptureSettings {
    OutputPattern output;
    PassId pass = PassId::Image;
    bool synchronous = false;      // glReadPixels and encoding on the render thread
    int pngLevel = 1;
    int encoderThreads = 0;        // 0: defaultEncoderThreads()
    std::size_t memoryCapBytes = std::size_t(256) << 20;
    VideoSettings video;
    double fps = 60;               // the video's frame rate
    int rawStreamFd = 1;           // where "--out -" writes (stdout)
};

class FrameCapture {
public:
    // Creates the sink (starting ffmpeg for a video), the encoder threads and the readback ring.
    static Result<std::unique_ptr<FrameCapture>> create(const CaptureSettings& settings, const Renderer& renderer);

    // Captures the frame the renderer has just rendered (its number is `frame`).
    Status capture(const Renderer& renderer, int frame);
    // Hands readbacks that have completed to the encoders, without waiting; call once a frame.
    Status poll();
    // Waits for every readback and every encoder, then completes the output. Without a
    // successful finish(), destruction discards incomplete output.
    Status finish();

    std::uint64_t bytesWritten() const { return pool_->bytesWritten(); }
    int encoderThreads() const { return pool_->threads(); }

private:
    FrameCapture() = default;
    Status collectOldest();

    CaptureSettings settings_;
    int width_ = 0, height_ = 0;
    PixelFormat format_ = PixelFormat::Rgba8;
    std::unique_ptr<FrameSink> sink_;    // declared before pool_: the pool's threads use it
    std::unique_ptr<EncoderPool> pool_;
    std::optional<ReadbackRing> ring_;
};

}  // namespace toyhost
