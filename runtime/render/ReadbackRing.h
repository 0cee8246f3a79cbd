// ReadbackRing: reads frames back without stalling the render thread. Each readback goes into
// one of a ring of pixel-pack buffers and is followed by a fence; the pixels are copied out only
// once the fence has signalled, typically while a later frame renders. Needs a current GL
// context for its whole life.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "image/Image.h"
#include "core/Result.h"
#include "gl/GlObjects.h"

namespace toyhost {

class ReadbackRing {
public:
    // Three slots: one being filled by the GPU, one waiting to be copied out, one spare so that
    // starting the next readback never waits for the copy.
    static constexpr int kDefaultSlots = 3;
    static Result<ReadbackRing> create(int width, int height, PixelFormat format, int slots = kDefaultSlots);

    bool empty() const { return pending_ == 0; }
    bool full() const { return pending_ == static_cast<int>(slots_.size()); }
    std::size_t frameBytes() const { return bytes_; }
    PixelFormat format() const { return format_; }
    int oldestFrame() const { return slots_[oldest_].frame; }

    // Queues a readback of `framebuffer`'s colour (the whole canvas) for frame `frame`; returns
    // at once. Requires !full().
    void start(unsigned int framebuffer, int frame);
    // True when the oldest pending readback has completed (does not wait). Requires !empty().
    bool oldestReady();
    // Waits for the oldest pending readback, copies its pixels (rows bottom first) into `out`
    // (exactly frameBytes() long) and frees its slot. Requires !empty().
    Status takeOldest(std::span<std::byte> out);
    // Forgets the oldest readback without reading it (a frame the recorder drops).
    void dropOldest();

private:
    struct Slot {
        GlBuffer buffer;
        GlFence fence;
        int frame = 0;
    };
    ReadbackRing() = default;

    int width_ = 0, height_ = 0;
    PixelFormat format_ = PixelFormat::Rgba8;
    std::size_t bytes_ = 0;
    std::vector<Slot> slots_;
    int oldest_ = 0;   // index of the oldest pending slot
    int pending_ = 0;
};

// A synchronous readback of `framebuffer` into `out` (frameBytes long), for the synchronous
// capture path and for comparing against the ring.
void readFramebuffer(unsigned int framebuffer, int width, int height, PixelFormat format, std::span<std::byte> out);

}  // namespace toyhost
