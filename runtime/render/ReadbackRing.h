// ReadbackRing: reads a recording's frames back without stalling the render thread: PendingReads
// (a pixel-pack buffer and a fence per read) limited to a few frames of one size and format, the
// pixels copied out once the fence has signalled, typically while a later frame renders. Needs a
// current GL context for its whole life.
#pragma once

#include <cstddef>
#include <span>

#include "core/Result.h"
#include "image/Image.h"
#include "render/PendingReads.h"

namespace toyhost {

class ReadbackRing {
public:
    // Three slots: one being filled by the GPU, one waiting to be copied out, one spare so that
    // starting the next readback never waits for the copy.
    static constexpr int kDefaultSlots = 3;
    // Makes the slots' buffers now: a failure to allocate them shows here, not mid-run. `gpu`:
    // the context's activity, where a wait for a readback publishes the pass still drawing.
    static Result<ReadbackRing> create(int width, int height, PixelFormat format, int slots = kDefaultSlots,
                                       GpuActivity* gpu = nullptr);

    bool empty() const { return reads_.size() == 0; }
    bool full() const { return reads_.size() == slots_; }
    int pending() const { return static_cast<int>(reads_.size()); }
    std::size_t frameBytes() const { return bytes_; }
    PixelFormat format() const { return format_; }
    int oldestFrame() const { return reads_.oldest().frame; }

    // Queues a readback of `framebuffer`'s colour (the whole canvas) for frame `frame`; returns
    // at once. Requires !full().
    Status start(unsigned int framebuffer, int frame);
    // True when the oldest pending readback has completed (does not wait). Requires !empty().
    bool oldestReady() const { return reads_.oldestDone(); }
    // Waits for the oldest pending readback, copies its pixels (rows bottom first) into `out`
    // (exactly frameBytes() long) and frees its slot. Requires !empty().
    Status takeOldest(std::span<std::byte> out);
    // Forgets the oldest readback without reading it (a frame the recorder drops).
    void dropOldest() { (void)reads_.releaseOldest(); }

private:
    ReadbackRing() = default;

    PendingReads reads_;
    int width_ = 0, height_ = 0;
    PixelFormat format_ = PixelFormat::Rgba8;
    std::size_t bytes_ = 0;
    std::size_t slots_ = 0;
};

// A synchronous readback of `framebuffer` into `out` (frameBytes long), for the synchronous
// capture path and for comparing against the ring; the wait is published on `gpu` when given.
void readFramebuffer(unsigned int framebuffer, int width, int height, PixelFormat format, std::span<std::byte> out,
                     GpuActivity* gpu = nullptr);

}  // namespace toyhost
