// FrameSink: where captured frames end up (one image file per frame, a byte stream, an ffmpeg
// process). Encoder threads call write(); the sink says whether frames may be written in
// parallel or must arrive one at a time in frame order. No GL needed.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <vector>

#include "capture/CapturedFrame.h"
#include "core/Result.h"
#include "image/ImageWriters.h"

namespace toyhost {

// Per-thread working memory for conversions (float to 8 bit, row flips, PNG row tables, EXR
// rows), kept between frames so that encoding allocates no pixel-sized buffer once the first frame
// has been written. (File names and the codec libraries' own state are still made per file.)
struct EncodeScratch {
    std::vector<std::uint8_t> bytes;
    std::vector<std::uint8_t> rows;
    ImageScratch image;
};

class FrameSink {
public:
    virtual ~FrameSink() = default;

    // True when frames must reach write() one at a time, in frame order (streams). False when each
    // frame is independent (its own file) and several threads may write at once, in any order.
    virtual bool ordered() const = 0;
    // Writes one frame. Called from encoder threads (never concurrently when ordered()).
    virtual Status write(const CapturedFrame& frame, EncodeScratch& scratch) = 0;
    // After the last frame: completes the output (a stream is ended and its file put in place).
    virtual Status close() { return okStatus(); }
    // After a failure: removes whatever output is incomplete. Files already complete are kept.
    virtual void discard() {}
    // Called from another thread to make a write() that is blocked (a reader that stopped
    // reading, a stalled encoder process) return soon with an error. Afterwards the sink is only
    // discarded.
    virtual void cancel() {}

    // Bytes written so far; read from any thread (progress display).
    std::uint64_t bytesWritten() const { return bytesWritten_.load(std::memory_order_relaxed); }
    // Seconds spent encoding (compressing, converting) and writing (files, pipes), summed over
    // the encoder threads: the run's summary shows where capture time went.
    double encodeSeconds() const { return encodeNanos_.load(std::memory_order_relaxed) * 1e-9; }
    double writeSeconds() const { return writeNanos_.load(std::memory_order_relaxed) * 1e-9; }

protected:
    void addBytesWritten(std::uint64_t bytes) { bytesWritten_.fetch_add(bytes, std::memory_order_relaxed); }
    // Adds the time since `since` to the encode or write total and returns now.
    using Clock = std::chrono::steady_clock;
    Clock::time_point addEncodeTime(Clock::time_point since) { return addTime(encodeNanos_, since); }
    Clock::time_point addWriteTime(Clock::time_point since) { return addTime(writeNanos_, since); }
    void encodeNanos(double seconds) { encodeNanos_.fetch_add(static_cast<std::int64_t>(seconds * 1e9), std::memory_order_relaxed); }
    void writeNanos(double seconds) { writeNanos_.fetch_add(static_cast<std::int64_t>(seconds * 1e9), std::memory_order_relaxed); }

private:
    static Clock::time_point addTime(std::atomic<std::int64_t>& total, Clock::time_point since) {
        const Clock::time_point now = Clock::now();
        total.fetch_add(std::chrono::duration_cast<std::chrono::nanoseconds>(now - since).count(),
                        std::memory_order_relaxed);
        return now;
    }
    std::atomic<std::uint64_t> bytesWritten_{0};
    std::atomic<std::int64_t> encodeNanos_{0};
    std::atomic<std::int64_t> writeNanos_{0};
};

}  // namespace toyhost
