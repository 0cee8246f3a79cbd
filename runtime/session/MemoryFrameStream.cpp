// MemoryFrameStream: the pacing, the reads and the hand-over; which frames are read and when they
// are handed over is capture/FrameStream's rule.
#include "session/MemoryFrameStream.h"

#include "session/SessionCore.h"

namespace toyhost {

MemoryFrameStream::MemoryFrameStream(SessionCore& core, const MemoryStreamRequest& request)
    : core_(core),
      request_(request),
      stream_(FrameStreamSettings{request.frames, request.every, request.inFlight, request.first}),
      reads_(&core.context().gpuActivity()),
      drawing_(&core.context().gpuActivity()) {}

Result<std::unique_ptr<MemoryFrameStream>> MemoryFrameStream::open(SessionCore& core, const MemoryStreamRequest& request) {
    std::unique_ptr<MemoryFrameStream> stream(new MemoryFrameStream(core, request));
    const PassOutput output = core.output(request.pass);
    if (Status reserved = stream->reads_.reserve(frameBytes(output.width, output.height, output.format),
                                                 static_cast<std::size_t>(request.inFlight));
        !reserved)
        return reserved.error();
    return stream;
}

Status MemoryFrameStream::start(int) {
    const PassOutput output = core_.output(request_.pass);
    return reads_.start(output.framebuffer, {core_.frame() - 1, output.width, output.height, output.format});
}

Status MemoryFrameStream::handOverOldest() {
    const PendingReads::Read read = reads_.oldest();
    // mapOldest() tells the watchdog which pass the GPU is still drawing while it waits.
    Result<std::span<const std::byte>> pixels = reads_.mapOldest();
    if (!pixels) {
        (void)reads_.releaseOldest();
        return pixels.error();
    }
    const MemoryFrame frame{read.frame, read.width, read.height, read.format, pixels->data()};
    bool goOn = false;
    try {
        goOn = (*take_)(frame);
    } catch (...) {
        (void)reads_.releaseOldest();  // unmapped before the consumer's exception leaves
        throw;
    }
    if (!goOn) stream_.requestStop();
    return reads_.releaseOldest();
}

Result<bool> MemoryFrameStream::advance(const StepFrame& step, const TakeFrame& take) {
    if (stream_.stopRequested()) {
        drop();
        return false;
    }
    take_ = &take;
    Status done = okStatus();
    if (rendered_ < request_.frames) {
        done = drawing_.waitBelow(kFramesAhead);
        if (done) done = step(rendered_);
        if (done) {
            const int index = rendered_++;
            drawing_.submitted();
            done = stream_.rendered(index, *this);
        }
    }
    if (done && rendered_ >= request_.frames) done = stream_.finish(*this);
    take_ = nullptr;
    if (!done) {
        drop();
        return done.error();
    }
    if (stream_.stopRequested()) {
        drop();
        return false;
    }
    return rendered_ < request_.frames || reads_.size() > 0;
}

void MemoryFrameStream::drop() {
    reads_.clear();
    drawing_.clear();
}

}  // namespace toyhost
