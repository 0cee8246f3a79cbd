// PendingReads: framebuffer reads queued without waiting (each into a pixel-pack buffer, followed
// by a fence) and taken in the order they were queued, each with its own size and format; the
// buffers are reused. The library Session's queued reads (queueRead / takeRead); a recording uses
// the fixed-size ReadbackRing. Needs its GL context current for its whole life.
#pragma once

#include <cstddef>
#include <deque>
#include <span>
#include <vector>

#include "core/Result.h"
#include "gl/GlObjects.h"
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

    std::size_t size() const { return pending_.size(); }
    // The oldest read not yet taken. Requires size() > 0.
    const Read& oldest() const { return pending_.front().read; }

    // Queues a read of `framebuffer`'s colour (read.width x read.height from the origin) and
    // returns at once.
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
    std::deque<Pending> pending_;
    // Buffers of taken reads, by size, for the next reads (a few: a session reads one size).
    std::vector<std::pair<std::size_t, GlBuffer>> spare_;
};

}  // namespace toyhost
