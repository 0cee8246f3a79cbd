#include "run/FrameCapture.h"

#include "capture/FileSinks.h"

namespace toyhost {

Result<std::unique_ptr<FrameCapture>> FrameCapture::create(const CaptureSettings& settings, const Renderer& renderer) {
    std::unique_ptr<FrameCapture> capture(new FrameCapture());
    capture->settings_ = settings;
    capture->width_ = renderer.width();
    capture->height_ = renderer.height();
    capture->format_ = renderer.outputIsFloat(settings.pass) ? PixelFormat::Rgba32f : PixelFormat::Rgba8;

    switch (settings.output.format()) {
        case OutputFormat::Png:
        case OutputFormat::Exr:
            capture->sink_ = std::make_unique<ImageSequenceSink>(settings.output, settings.pngLevel);
            break;
        case OutputFormat::RawStream:
            capture->sink_ = std::make_unique<RawStreamSink>(settings.rawStreamFd, "stdout");
            break;
        case OutputFormat::Video: {
            Result<std::unique_ptr<VideoSink>> video = VideoSink::start(
                settings.output.pathFor(0), capture->width_, capture->height_, settings.fps, settings.video);
            if (!video) return video.error();
            capture->sink_ = std::move(*video);
            break;
        }
    }
    const int threads = settings.synchronous ? 0
                        : settings.encoderThreads > 0 ? settings.encoderThreads
                                                      : defaultEncoderThreads();
    capture->pool_ = std::make_unique<EncoderPool>(*capture->sink_, threads, settings.memoryCapBytes);
    if (!settings.synchronous) {
        Result<ReadbackRing> ring = ReadbackRing::create(capture->width_, capture->height_, capture->format_);
        if (!ring) return ring.error();
        capture->ring_.emplace(std::move(*ring));
    }
    return capture;
}

Status FrameCapture::capture(const Renderer& renderer, int frame) {
    const unsigned int framebuffer = renderer.outputFramebuffer(settings_.pass);
    if (!ring_) {
        Result<std::vector<std::byte>> pixels = pool_->acquire(frameBytes(width_, height_, format_));
        if (!pixels) return pixels.error();
        readFramebuffer(framebuffer, width_, height_, format_, *pixels);
        return pool_->submit(CapturedFrame{frame, width_, height_, format_, std::move(*pixels)});
    }
    if (ring_->full())
        if (Status collected = collectOldest(); !collected) return collected;
    ring_->start(framebuffer, frame);
    return poll();
}

Status FrameCapture::poll() {
    while (ring_ && !ring_->empty() && ring_->oldestReady())
        if (Status collected = collectOldest(); !collected) return collected;
    return okStatus();
}

Status FrameCapture::collectOldest() {
    // Blocks while the encoders hold the memory cap: back-pressure reaches the render loop here.
    Result<std::vector<std::byte>> pixels = pool_->acquire(ring_->frameBytes());
    if (!pixels) return pixels.error();
    const int frame = ring_->oldestFrame();
    if (Status copied = ring_->takeOldest(*pixels); !copied) return copied;
    return pool_->submit(CapturedFrame{frame, width_, height_, format_, std::move(*pixels)});
}

Status FrameCapture::finish() {
    while (ring_ && !ring_->empty())
        if (Status collected = collectOldest(); !collected) return collected;
    return pool_->finish();
}

}  // namespace toyhost
