// EncoderPool: moves captured frames off the render thread. A FrameQueue (bounded in bytes)
// feeds N encoder threads that hand each frame to a FrameSink; an ordered sink gets exactly one
// thread, so its frames stay in frame order. With 0 threads every frame is written on the
// caller's thread (the synchronous path). The first error from any thread stops the pool and is
// returned to the producer at its next call. No GL needed.
#pragma once

#include <atomic>

#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "capture/FrameQueue.h"
#include "capture/FrameSink.h"

namespace toyhost {

// max(1, hardware threads - 1): on a machine whose renderer is the CPU (llvmpipe) the encoders
// and the rasterizer share the cores, and one core left to the render thread keeps it fed.
int defaultEncoderThreads();
// The most threads an automatic pool grows to: the hardware threads.
int maxEncoderThreads();

class EncoderPool {
public:
    // `threads` 0: synchronous. An ordered sink uses one thread whatever `threads` says (> 0).
    // Threads the system refuses to start are done without (threads() counts those running).
    // `growTo` > `threads` (parallel sinks only): each time the producer finds the memory cap
    // reached (the encoders are slower than rendering), one more thread is started, up to
    // `growTo`; so the count follows the measured encode/render ratio.
    EncoderPool(FrameSink& sink, int threads, std::size_t memoryCapBytes, int growTo = 0);
    // Stops the threads; if finish() was not called (or failed) the sink's output is discarded.
    ~EncoderPool();
    EncoderPool(const EncoderPool&) = delete;
    EncoderPool& operator=(const EncoderPool&) = delete;

    // A pixel buffer for the next frame; blocks while the queue holds its memory cap
    // (back-pressure). Fails with the first encoder error once one happened, or when `stop`
    // (asked while it waits) says the run is stopping (Code::CaptureStopped).
    Result<std::vector<std::byte>> acquire(std::size_t bytes, const std::function<bool()>& stop = {});
    // As acquire(), but never waits: std::nullopt when the cap is reached right now.
    Result<std::optional<std::vector<std::byte>>> tryAcquire(std::size_t bytes);
    // Queues a frame whose pixels came from acquire(); synchronous pools write it right away.
    Status submit(CapturedFrame frame);
    // Writes everything queued, stops the threads and closes the sink; the first error wins.
    Status finish();

    // Threads running (read on the producer's thread).
    int threads() const { return static_cast<int>(workers_.size()); }
    std::uint64_t bytesWritten() const { return sink_.bytesWritten(); }
    // Frames the sink has written completely so far.
    int framesWritten() const { return framesWritten_.load(); }
    // Gives up: frames still queued are dropped, the threads stop (a thread blocked in the sink is
    // released first) and the sink discards what is incomplete. Idempotent; the destructor calls
    // it when finish() did not succeed.
    void abandon();
    const FrameQueue& queue() const { return queue_; }

private:
    void work();
    Status writeGuarded(const CapturedFrame& frame, EncodeScratch& scratch);
    void fail(Error error);
    std::optional<Error> firstError() const;
    void stop();
    void startWorker();
    void growIfBehind();

    FrameSink& sink_;
    FrameQueue queue_;
    EncodeScratch inlineScratch_;
    std::vector<std::thread> workers_;
    mutable std::mutex errorMutex_;
    std::optional<Error> error_;
    std::atomic<int> framesWritten_{0};
    int growTo_ = 0;
    bool abandoned_ = false;
    bool finished_ = false;
};

}  // namespace toyhost
