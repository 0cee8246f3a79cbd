// FrameQueue: the bounded hand-over between the thread that reads frames back and the encoder
// threads. Memory is bounded in bytes, not frames: pixel buffers come from a recycling pool whose
// total size stays under a cap, and asking for a buffer blocks while the cap is reached (back-
// pressure) instead of growing or dropping frames. Frames leave in the order they were pushed.
// Thread-safe; no GL needed.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

#include "capture/CapturedFrame.h"

namespace toyhost {

class FrameQueue {
public:
    // A frame larger than `capBytes` is still let through when nothing else is held, so a run
    // never deadlocks on a small cap; it then holds one frame at a time.
    explicit FrameQueue(std::size_t capBytes);

    // A buffer of exactly `bytes` bytes, recycled when one is free. Blocks while taking it would
    // pass the cap (or, with `wait` false, returns std::nullopt at once). std::nullopt once the
    // queue was aborted, or when `cancelled` (asked every 50 ms while blocked) says so.
    std::optional<std::vector<std::byte>> acquire(std::size_t bytes, bool wait = true,
                                                  const std::function<bool()>& cancelled = {});
    // Hands a frame (whose buffer came from acquire) to the consumers. Never blocks.
    void push(CapturedFrame frame);
    // The oldest frame; blocks until there is one. std::nullopt when closed and drained, or aborted.
    std::optional<CapturedFrame> pop();
    // Gives a frame's buffer back to the pool, for acquire to reuse.
    void recycle(std::vector<std::byte> buffer);

    // No more frames will be pushed; pop drains what is queued, then returns std::nullopt.
    void close();
    // Stop now: queued frames are dropped, acquire and pop return std::nullopt from now on.
    void abort();

    std::size_t capBytes() const { return cap_; }
    // Bytes of pixel buffers alive (queued, being encoded, or pooled for reuse), and the most
    // that ever were: both stay <= capBytes() unless a single frame is larger than the cap.
    std::size_t allocatedBytes() const;
    std::size_t peakAllocatedBytes() const;
    // Threads blocked right now in acquire() (waiting for memory) and in pop() (waiting for a
    // frame): lets tests wait for "blocked" instead of sleeping and hoping.
    std::size_t blockedProducers() const;
    std::size_t blockedConsumers() const;
    // Frames pushed and not yet popped.
    std::size_t queuedFrames() const;

private:
    const std::size_t cap_;
    mutable std::mutex mutex_;
    std::condition_variable bufferFreed_;
    std::condition_variable frameQueued_;
    std::deque<CapturedFrame> frames_;
    std::vector<std::vector<std::byte>> pool_;
    std::size_t allocated_ = 0;
    std::size_t peak_ = 0;
    std::size_t blockedProducers_ = 0;
    std::size_t blockedConsumers_ = 0;
    bool closed_ = false;
    bool aborted_ = false;
};

}  // namespace toyhost
