// FrameSink: where captured frames end up (one image file per frame, a byte stream, an ffmpeg
// process). Encoder threads call write(); the sink says whether frames may be written in
// parallel or must arrive one at a time in frame order. No GL needed.
#pragma once

#include <atomic>
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

protected:
    void addBytesWritten(std::uint64_t bytes) { bytesWritten_.fetch_add(bytes, std::memory_order_relaxed); }

private:
    std::atomic<std::uint64_t> bytesWritten_{0};
};

}  // namespace toyhost
