// PendingReads: framebuffer reads queued without waiting (each into a pixel-pack buffer, followed
// by a fence) and taken in the order they were queued, each with its own size and format; the
// buffers are reused. The memory frame stream's reads (session/MemoryFrameStream.h), and under a
// recording's ReadbackRing. Needs its GL context current for its whole life.
#pragma once

#include <cstddef>
#include <deque>
#include <span>
#include <vector>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "gl/GpuActivity.h"
#include "image/Image.h"

namespace toyhost {

class PendingReads {
public:
    struct Read {
        int frame = 0;  // what the caller says the read shows
        int width = 0;
        int height = 0;
        PixelFormat format = PixelFormat::Rgba8;  // the framebuffer's: the values as read
    };

    // `gpu`: the context's activity (GlContext::gpuActivity()), where mapOldest() publishes the
    // pass the GPU is still drawing while it waits; null: nothing is published.
    explicit PendingReads(GpuActivity* gpu = nullptr) : gpu_(gpu) {}

    std::size_t size() const { return pending_.size(); }
    // The oldest read not yet taken. Requires size() > 0.
    const Read& oldest() const { return pending_.front().read; }

    // Makes `count` buffers of `bytes` ready for later reads (kept while unused), so that reads of
    // that size allocate nothing and a failure to allocate shows here. Errors name GL's error.
    Status reserve(std::size_t bytes, std::size_t count);
    // Queues a read of `framebuffer`'s colour (read.width x read.height from the origin) and
    // returns at once. A GL error is checked only where a buffer had to be made (not per read).
    Status start(unsigned int framebuffer, const Read& read);
    // Whether the oldest read is complete (mapOldest() would not wait). Requires size() > 0.
    bool oldestDone() const;
    // Waits for the oldest read and maps its pixels (rows bottom first, read.format's values) for
    // reading, until release(). Requires size() > 0.
    Result<std::span<const std::byte>> mapOldest();
    // Unmaps the oldest read's pixels and forgets it (its buffer is kept for a later read).
    Status releaseOldest();
    // Forgets every read not yet taken.
    void clear();

private:
    struct Pending {
        Read read;
        std::size_t bytes = 0;
        GlBuffer buffer;
        GlFence fence;
        bool mapped = false;
    };
    GpuActivity* gpu_ = nullptr;
    std::deque<Pending> pending_;
    Status newBuffer(std::size_t bytes, GlBuffer& out);

    // Buffers of taken reads, by size, for the next reads (a few: a session reads one size).
    std::vector<std::pair<std::size_t, GlBuffer>> spare_;
    std::size_t spareLimit_ = 4;
};

}  // namespace toyhost
