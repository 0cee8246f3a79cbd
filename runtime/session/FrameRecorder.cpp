#include "session/FrameRecorder.h"

#include "core/Defaults.h"

#include <algorithm>
#include <chrono>

namespace toyhost {

// The recording's reads as its FrameStream drives them: the readback ring's, or none pending when
// frames are read synchronously (Cube A, --sync-capture: start() reads and encodes at once).
class FrameRecorder::Reads final : public FrameReads {
public:
    explicit Reads(FrameRecorder& recorder) : recorder_(recorder) {}
    const RenderedFrame* rendered = nullptr;  // the frame start() reads

    int pending() const override { return recorder_.ring_ ? recorder_.ring_->pending() : 0; }
    Status start(int) override { return recorder_.capture(*rendered); }
    bool oldestDone() const override { return recorder_.ring_->oldestReady(); }
    Status handOverOldest() override { return recorder_.collectOldest(); }
    void dropAll() override {
        while (recorder_.ring_ && !recorder_.ring_->empty()) recorder_.ring_->dropOldest();
    }

private:
    FrameRecorder& recorder_;
};

Result<std::unique_ptr<FrameRecorder>> FrameRecorder::create(const RecorderSettings& settings, const Player& player) {
    std::unique_ptr<FrameRecorder> recorder(new FrameRecorder());
    recorder->context_ = player.sharedContext();
    recorder->settings_ = settings;
    const PassOutput output = player.output(settings.pass);
    recorder->width_ = output.width;
    recorder->height_ = output.height;
    recorder->format_ = output.format;
    if (settings.pass == PassId::CubeA) {
        // Cube A: the six faces side by side in GL order (+X, -X, +Y, -Y, +Z, -Z), read
        // synchronously (see captureCube).
        recorder->width_ = 6 * defaults::kCubeBufferSize;
        recorder->height_ = defaults::kCubeBufferSize;
        recorder->format_ = PixelFormat::Rgba32f;
    }

    OutputSinkRequest request = settings.sink;
    request.width = recorder->width_;
    request.height = recorder->height_;
    Result<OutputSink> sink = makeOutputSink(request);
    if (!sink) return sink.error();
    recorder->sink_ = std::move(sink->sink);
    recorder->videoEncoder_ = std::move(sink->videoEncoder);
    recorder->videoEncoderChoice_ = std::move(sink->videoEncoderChoice);
    const int threads = settings.synchronous ? 0
                        : settings.encoderThreads > 0 ? settings.encoderThreads
                                                      : defaultEncoderThreads();
    // An automatic count starts at defaultEncoderThreads() and grows to every core when rendering
    // outruns the encoders (a GPU, a cheap shader); --encoder-threads N is exactly N.
    const int growTo = settings.encoderThreads > 0 ? 0 : maxEncoderThreads();
    recorder->pool_ = std::make_unique<EncoderPool>(*recorder->sink_, threads, settings.memoryCapBytes, growTo);
    if (!settings.synchronous && settings.pass != PassId::CubeA) {
        Result<ReadbackRing> ring = ReadbackRing::create(recorder->width_, recorder->height_, recorder->format_,
                                                         ReadbackRing::kDefaultSlots, &recorder->context_->gpuActivity());
        if (!ring) return ring.error();
        recorder->ring_.emplace(std::move(*ring));
    }
    recorder->stream_.emplace(FrameStreamSettings{settings.frames, settings.captureEvery, ReadbackRing::kDefaultSlots});
    recorder->reads_ = std::make_unique<Reads>(*recorder);
    return recorder;
}

FrameRecorder::~FrameRecorder() {
    // The encoders stop first (discarding incomplete output), then the readback buffers go while
    // their context is current.
    pool_.reset();
    if (context_) (void)context_->makeCurrent();
    ring_.reset();
}

RecorderSettings recorderSettings(const SessionPlan& run, RunActivity* activity, std::function<bool()> stopRequested) {
    const SessionOptions& o = run.options;
    RecorderSettings settings;
    settings.sink.output = *run.output;
    settings.sink.pngLevel = *o.pngLevel;
    settings.sink.exr = o.exr;
    settings.sink.video = o.video;
    settings.sink.fps = o.settings.fps.value_or(defaults::kFps);
    settings.sink.rawStreamFd = o.rawStreamFd;
    settings.pass = o.capturePass;
    settings.frames = *o.frames;
    settings.captureEvery = *o.captureEvery;
    settings.synchronous = o.syncCapture;
    settings.encoderThreads = o.encoderThreads;
    settings.memoryCapBytes = *o.captureMemoryBytes;
    settings.dropWhenBusy = o.interactive && !o.settings.fps;
    settings.activity = activity;
    settings.stopRequested = std::move(stopRequested);
    return settings;
}

Status FrameRecorder::captureCube(const Player& player, int frame) {
    Result<std::optional<std::vector<std::byte>>> pixels = takeBuffer(frameBytes(width_, height_, format_));
    if (!pixels) return pixels.error();
    if (!*pixels) {
        ++captured_;
        return dropped(frame);
    }
    float* strip = reinterpret_cast<float*>((*pixels)->data());
    int size = 0;
    for (int face = 0; face < 6; ++face) {
        player.readCubeFace(face, cubeFace_, size);
        if (size != height_) return Error("capture: Cube A's faces are not " + std::to_string(height_) + " wide", Code::CaptureSize);
        for (int y = 0; y < size; ++y)
            std::copy_n(cubeFace_.begin() + static_cast<std::ptrdiff_t>(y) * size * 4, size * 4,
                        strip + (static_cast<std::ptrdiff_t>(y) * width_ + static_cast<std::ptrdiff_t>(face) * size) * 4);
    }
    ++captured_;
    scanFloatFrame(frame, **pixels);
    return pool_->submit(CapturedFrame{frame, width_, height_, format_, std::move(**pixels)});
}

namespace {
using Clock = std::chrono::steady_clock;
// Adds the seconds since construction to `total` when it goes out of scope.
struct Stopwatch {
    double& total;
    Clock::time_point from = Clock::now();
    ~Stopwatch() { total += std::chrono::duration<double>(Clock::now() - from).count(); }
};
}  // namespace

Status FrameRecorder::capture(const RenderedFrame& rendered) {
    const int frame = rendered.frame;
    if (settings_.pass == PassId::CubeA) return captureCube(rendered.player, frame);
    const PassOutput& output = rendered.output;
    if (output.width != width_ || output.height != height_)
        return Error("capture: the canvas changed size during a recording (" + std::to_string(width_) + "x" +
                         std::to_string(height_) + " -> " + std::to_string(output.width) + "x" +
                         std::to_string(output.height) + ")",
                     Code::CaptureSize);
    if (!ring_) {
        Result<std::optional<std::vector<std::byte>>> pixels = takeBuffer(frameBytes(width_, height_, format_));
        if (!pixels) return pixels.error();
        if (!*pixels) {
            ++captured_;
            return dropped(frame);
        }
        {
            Stopwatch readback{readbackSeconds_};
            readFramebuffer(output.framebuffer, width_, height_, format_, **pixels, &context_->gpuActivity());
        }
        ++captured_;
        scanFloatFrame(frame, **pixels);
        return pool_->submit(CapturedFrame{frame, width_, height_, format_, std::move(**pixels)});
    }
    // The stream freed a slot first (its in-flight bound is the ring's size).
    {
        Stopwatch readback{readbackSeconds_};
        if (Status started = ring_->start(output.framebuffer, frame); !started) return started;
    }
    ++captured_;
    return okStatus();
}

Status FrameRecorder::rendered(const RenderedFrame& frame) {
    reads_->rendered = &frame;
    Status handed = stream_->rendered(frame.frame, *reads_);
    reads_->rendered = nullptr;
    return handed;
}

Result<std::optional<std::vector<std::byte>>> FrameRecorder::takeBuffer(std::size_t bytes) {
    if (settings_.dropWhenBusy) {
        return pool_->tryAcquire(bytes);
    }
    // Blocks while the encoders hold the memory cap: back-pressure reaches the render loop here.
    if (settings_.activity) settings_.activity->begin(RunActivity::Phase::WaitingForOutput);
    Stopwatch waiting{waitSeconds_};
    Result<std::vector<std::byte>> buffer = pool_->acquire(bytes, settings_.stopRequested);
    if (settings_.activity) settings_.activity->idle();
    if (!buffer) return buffer.error();
    return std::optional<std::vector<std::byte>>(std::move(*buffer));
}

Status FrameRecorder::collectOldest() {
    Result<std::optional<std::vector<std::byte>>> pixels = takeBuffer(ring_->frameBytes());
    if (!pixels) return pixels.error();
    if (!*pixels) {
        const int frame = ring_->oldestFrame();
        ring_->dropOldest();
        return dropped(frame);
    }
    const int frame = ring_->oldestFrame();
    Stopwatch readback{readbackSeconds_};
    if (Status copied = ring_->takeOldest(**pixels); !copied) return copied;
    scanFloatFrame(frame, **pixels);
    return pool_->submit(CapturedFrame{frame, width_, height_, format_, std::move(**pixels)});
}

void FrameRecorder::scanFloatFrame(int frame, const std::vector<std::byte>& pixels) {
    if (format_ != PixelFormat::Rgba32f || firstNonFinite_) return;
    const std::span<const float> values(reinterpret_cast<const float*>(pixels.data()), pixels.size() / sizeof(float));
    const NonFiniteFind found = findNonFinite(values, width_);
    if (found.count()) firstNonFinite_.emplace(frame, found);
}

Status FrameRecorder::dropped(int frame) {
    droppedFrames_.push_back(frame);
    return okStatus();
}

ConsumedFrames FrameRecorder::consumed() const {
    return {pool_->bytesWritten(),
            pool_->threads(),
            videoEncoder_,
            CaptureTimes{0, readbackSeconds_, waitSeconds_, sink_->encodeSeconds(), sink_->writeSeconds()},
            droppedFrames_,
            firstNonFinite_};
}

FrameConsumer::Abandoned FrameRecorder::abandon() {
    if (settings_.activity) settings_.activity->begin(RunActivity::Phase::Abandoning);
    pool_->abandon();
    if (settings_.activity) settings_.activity->idle();
    const int written = pool_->framesWritten();
    return {written, captured_ - written - static_cast<int>(droppedFrames_.size())};
}

Status FrameRecorder::finish() {
    settings_.dropWhenBusy = false;  // what is still in the ring is written
    if (Status drained = stream_->finish(*reads_); !drained) return drained;
    // The encoders write the last frames and the sink closes (ffmpeg finishing a video): a stalled
    // encoder here is the watchdog's to end, as while rendering.
    if (settings_.activity) settings_.activity->begin(RunActivity::Phase::WaitingForOutput);
    Status finished = pool_->finish();
    if (settings_.activity) settings_.activity->idle();
    return finished;
}

}  // namespace toyhost
