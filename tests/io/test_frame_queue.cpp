// FrameQueue and EncoderPool without GL: frames keep their order, a slow consumer holds the
// producer back (back-pressure) instead of letting memory grow or frames drop, the memory cap
// holds, and the first encoder error stops the producer.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <optional>
#include <stdexcept>
#include <cstring>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "capture/EncoderPool.h"
#include "capture/FrameQueue.h"

using namespace toyhost;

namespace {

constexpr std::size_t kFrameBytes = 1000;

CapturedFrame stamped(int frame, std::vector<std::byte> pixels) {
    std::memcpy(pixels.data(), &frame, sizeof frame);  // the payload says which frame it is
    return CapturedFrame{frame, 1, 1, PixelFormat::Rgba8, std::move(pixels)};
}

int stampOf(const CapturedFrame& frame) {
    int value = -1;
    std::memcpy(&value, frame.pixels.data(), sizeof value);
    return value;
}

// A sink that takes its time, remembers what it got and can fail on a given frame.
class RecordingSink final : public FrameSink {
public:
    RecordingSink(bool ordered, std::chrono::milliseconds delay, int failAt = -1)
        : ordered_(ordered), delay_(delay), failAt_(failAt) {}
    bool ordered() const override { return ordered_; }
    Status write(const CapturedFrame& frame, EncodeScratch&) override {
        std::this_thread::sleep_for(delay_);
        if (frame.frame == failAt_) return Error{"disk full at frame " + std::to_string(frame.frame)};
        std::lock_guard lock(mutex_);
        frames.push_back(frame.frame);
        threads.push_back(std::this_thread::get_id());
        stampsMatch = stampsMatch && stampOf(frame) == frame.frame;
        addBytesWritten(frame.pixels.size());
        return okStatus();
    }
    Status close() override {
        closed = true;
        return okStatus();
    }
    void discard() override { discarded = true; }

    std::mutex mutex_;
    std::vector<int> frames;
    std::vector<std::thread::id> threads;  // which thread wrote each frame
    bool stampsMatch = true;
    std::atomic<bool> closed{false}, discarded{false};

private:
    bool ordered_;
    std::chrono::milliseconds delay_;
    int failAt_;
};

// Waits (yielding) until `condition` holds; false after 10 s, so a broken queue fails the test
// instead of hanging it. Tests wait for states ("the producer is blocked"), never for time.
template <class Condition>
bool eventually(Condition condition) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!condition()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::yield();
    }
    return true;
}

}  // namespace

TEST(FrameQueue, FramesLeaveInPushOrderAndBuffersAreRecycled) {
    FrameQueue queue(4 * kFrameBytes);
    for (int f = 0; f < 3; ++f) queue.push(stamped(f, *queue.acquire(kFrameBytes)));
    queue.close();
    std::vector<int> seen;
    while (auto frame = queue.pop()) {
        seen.push_back(stampOf(*frame));
        queue.recycle(std::move(frame->pixels));
    }
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
    // The three buffers are pooled; taking them again allocates nothing new.
    EXPECT_EQ(queue.allocatedBytes(), 3 * kFrameBytes);
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(queue.acquire(kFrameBytes));
    EXPECT_EQ(queue.peakAllocatedBytes(), 3 * kFrameBytes);
}

TEST(FrameQueue, SlowConsumerHoldsTheProducerBackUnderTheCap) {
    const std::size_t cap = 3 * kFrameBytes;
    FrameQueue queue(cap);
    constexpr int kFrames = 40;
    std::vector<int> seen;
    bool producerBlocked = false;
    std::size_t bytesWhenBlocked = 0;
    std::thread consumer([&] {
        // Consumes nothing until the producer has filled the cap and waits in acquire().
        producerBlocked = eventually([&] { return queue.blockedProducers() == 1; });
        bytesWhenBlocked = queue.allocatedBytes();
        while (auto frame = queue.pop()) {
            seen.push_back(stampOf(*frame));
            queue.recycle(std::move(frame->pixels));
        }
    });
    for (int f = 0; f < kFrames; ++f) {
        auto buffer = queue.acquire(kFrameBytes);
        ASSERT_TRUE(buffer);
        EXPECT_LE(queue.allocatedBytes(), cap);
        queue.push(stamped(f, std::move(*buffer)));
    }
    queue.close();
    consumer.join();
    // The producer ran ahead by exactly the cap (3 frames), then waited for the consumer.
    EXPECT_TRUE(producerBlocked);
    EXPECT_EQ(bytesWhenBlocked, cap);
    ASSERT_EQ(seen.size(), static_cast<std::size_t>(kFrames));
    for (int f = 0; f < kFrames; ++f) EXPECT_EQ(seen[f], f);
    EXPECT_LE(queue.peakAllocatedBytes(), cap);
}

TEST(FrameQueue, AFrameLargerThanTheCapPassesAlone) {
    FrameQueue queue(100);
    auto big = queue.acquire(1000);
    ASSERT_TRUE(big);
    std::atomic<bool> gotSecond{false};
    std::thread producer([&] {
        auto second = queue.acquire(1000);
        gotSecond = second.has_value();
    });
    ASSERT_TRUE(eventually([&] { return queue.blockedProducers() == 1; }));
    EXPECT_FALSE(gotSecond);  // waits: the first one holds the memory
    queue.recycle(std::move(*big));
    producer.join();
    EXPECT_TRUE(gotSecond);
}

TEST(FrameQueue, AbortWakesBlockedProducersAndConsumers) {
    FrameQueue queue(kFrameBytes);
    auto held = queue.acquire(kFrameBytes);
    std::atomic<int> woken{0};
    std::thread producer([&] { woken += !queue.acquire(kFrameBytes).has_value(); });
    std::thread consumer([&] { woken += !queue.pop().has_value(); });
    ASSERT_TRUE(eventually([&] { return queue.blockedProducers() == 1 && queue.blockedConsumers() == 1; }));
    EXPECT_EQ(woken, 0);
    queue.abort();
    producer.join();
    consumer.join();
    EXPECT_EQ(woken, 2);
}

TEST(FrameQueue, AProducerWaitingForMemoryLeavesWhenItsStopIsAsked) {
    FrameQueue queue(kFrameBytes);
    auto held = queue.acquire(kFrameBytes);
    std::atomic<bool> stop{false};
    std::atomic<int> result{-1};  // 1: got a buffer, 0: left without one
    std::thread producer([&] { result = queue.acquire(kFrameBytes, true, [&] { return stop.load(); }).has_value(); });
    ASSERT_TRUE(eventually([&] { return queue.blockedProducers() == 1; }));
    EXPECT_EQ(result, -1);  // still waiting: nothing freed, no stop
    stop = true;
    producer.join();
    EXPECT_EQ(result, 0);
    // The queue itself was not aborted: a buffer freed later is acquired as before.
    queue.recycle(std::move(*held));
    EXPECT_TRUE(queue.acquire(kFrameBytes, false).has_value());
}

TEST(EncoderPool, OrderedSinkGetsEveryFrameInOrderThroughASlowWriter) {
    RecordingSink sink(/*ordered=*/true, std::chrono::milliseconds(3));
    const std::size_t cap = 4 * kFrameBytes;
    EncoderPool pool(sink, /*threads=*/4, cap);
    EXPECT_EQ(pool.threads(), 1);  // ordered: one writer whatever was asked
    constexpr int kFrames = 30;
    for (int f = 0; f < kFrames; ++f) {
        auto buffer = pool.acquire(kFrameBytes);
        ASSERT_TRUE(buffer.ok()) << buffer.error().text();
        ASSERT_TRUE(pool.submit(stamped(f, std::move(*buffer))).ok());
        EXPECT_LE(pool.queue().allocatedBytes(), cap);
    }
    ASSERT_TRUE(pool.finish().ok());
    std::vector<int> expected(kFrames);
    for (int f = 0; f < kFrames; ++f) expected[f] = f;
    EXPECT_EQ(sink.frames, expected);
    EXPECT_TRUE(sink.stampsMatch);
    EXPECT_TRUE(sink.closed);
    EXPECT_FALSE(sink.discarded);
    EXPECT_LE(pool.queue().peakAllocatedBytes(), cap);
    EXPECT_EQ(pool.bytesWritten(), kFrames * kFrameBytes);
}

TEST(EncoderPool, ParallelSinkGetsEveryFrameExactlyOnce) {
    RecordingSink sink(/*ordered=*/false, std::chrono::milliseconds(2));
    const std::size_t cap = 3 * kFrameBytes;
    EncoderPool pool(sink, /*threads=*/3, cap);
    EXPECT_EQ(pool.threads(), 3);
    constexpr int kFrames = 40;
    for (int f = 0; f < kFrames; ++f) {
        auto buffer = pool.acquire(kFrameBytes);
        ASSERT_TRUE(buffer.ok());
        ASSERT_TRUE(pool.submit(stamped(f, std::move(*buffer))).ok());
    }
    ASSERT_TRUE(pool.finish().ok());
    std::set<int> unique(sink.frames.begin(), sink.frames.end());
    EXPECT_EQ(sink.frames.size(), static_cast<std::size_t>(kFrames));
    EXPECT_EQ(unique.size(), static_cast<std::size_t>(kFrames));
    EXPECT_TRUE(sink.stampsMatch);
    EXPECT_LE(pool.queue().peakAllocatedBytes(), cap);
}

TEST(EncoderPool, SynchronousPoolWritesOnTheCallersThread) {
    RecordingSink sink(/*ordered=*/false, std::chrono::milliseconds(0));
    EncoderPool pool(sink, /*threads=*/0, kFrameBytes);
    EXPECT_EQ(pool.threads(), 0);
    for (int f = 0; f < 5; ++f) {
        ASSERT_TRUE(pool.submit(stamped(f, *pool.acquire(kFrameBytes))).ok());
        EXPECT_EQ(sink.frames.size(), static_cast<std::size_t>(f + 1));  // written already
    }
    ASSERT_TRUE(pool.finish().ok());
    for (std::thread::id writer : sink.threads) EXPECT_EQ(writer, std::this_thread::get_id());
    EXPECT_EQ(pool.queue().peakAllocatedBytes(), kFrameBytes);  // one buffer, reused
}

TEST(EncoderPool, FirstErrorStopsTheProducerAndDiscardsTheOutput) {
    auto sink = std::make_unique<RecordingSink>(/*ordered=*/true, std::chrono::milliseconds(1), /*failAt=*/5);
    std::optional<Error> seen;
    {
        EncoderPool pool(*sink, 1, 2 * kFrameBytes);
        for (int f = 0; f < 100 && !seen; ++f) {
            auto buffer = pool.acquire(kFrameBytes);
            if (!buffer) {
                seen = buffer.error();
                break;
            }
            if (Status submitted = pool.submit(stamped(f, std::move(*buffer))); !submitted) seen = submitted.error();
        }
        if (!seen) {
            Status finished = pool.finish();
            ASSERT_FALSE(finished.ok());
            seen = finished.error();
        }
    }
    ASSERT_TRUE(seen);
    EXPECT_EQ(seen->first().message, "disk full at frame 5");
    EXPECT_TRUE(sink->discarded);
    EXPECT_FALSE(sink->closed);
    EXPECT_EQ(sink->frames, (std::vector<int>{0, 1, 2, 3, 4}));
}

namespace {

// A sink whose write throws on one frame, as a codec library or a bad_alloc might.
class ThrowingSink final : public FrameSink {
public:
    explicit ThrowingSink(int throwAt) : throwAt_(throwAt) {}
    bool ordered() const override { return false; }
    Status write(const CapturedFrame& frame, EncodeScratch&) override {
        if (frame.frame == throwAt_) throw std::runtime_error("codec exploded");
        return okStatus();
    }
    void discard() override { discarded = true; }
    std::atomic<bool> discarded{false};

private:
    int throwAt_;
};

// A sink whose write blocks until cancel(), like a pipe whose reader stopped reading.
class StalledSink final : public FrameSink {
public:
    bool ordered() const override { return true; }
    Status write(const CapturedFrame&, EncodeScratch&) override {
        std::unique_lock lock(mutex_);
        writing = true;
        woken_.wait(lock, [&] { return cancelled; });
        return Error("cancelled");
    }
    void cancel() override {
        std::lock_guard lock(mutex_);
        cancelled = true;
        woken_.notify_all();
    }
    void discard() override { discarded = true; }
    std::mutex mutex_;
    std::condition_variable woken_;
    bool writing = false, cancelled = false;
    std::atomic<bool> discarded{false};
};

}  // namespace

TEST(EncoderPool, AnExceptionInAnEncoderBecomesTheRunsError) {
    for (int threads : {0, 2}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        ThrowingSink sink(/*throwAt=*/2);
        std::optional<Error> seen;
        {
            EncoderPool pool(sink, threads, 2 * kFrameBytes);
            for (int f = 0; f < 50 && !seen; ++f) {
                auto buffer = pool.acquire(kFrameBytes);
                if (!buffer) seen = buffer.error();
                else if (Status s = pool.submit(stamped(f, std::move(*buffer))); !s) seen = s.error();
            }
            if (!seen) {
                Status finished = pool.finish();
                ASSERT_FALSE(finished.ok());
                seen = finished.error();
            }
        }
        ASSERT_TRUE(seen);
        EXPECT_NE(seen->text().find("codec exploded"), std::string::npos) << seen->text();
        EXPECT_TRUE(sink.discarded);
    }
}

TEST(EncoderPool, StoppingCancelsAStalledSinkInsteadOfWaitingForIt) {
    StalledSink sink;
    {
        EncoderPool pool(sink, 1, 4 * kFrameBytes);
        ASSERT_TRUE(pool.submit(stamped(0, *pool.acquire(kFrameBytes))).ok());
        ASSERT_TRUE(eventually([&] {
            std::lock_guard lock(sink.mutex_);
            return sink.writing;
        }));
    }  // destroyed without finish(): must cancel the write, join and discard, not hang
    EXPECT_TRUE(sink.cancelled);
    EXPECT_TRUE(sink.discarded);
}

TEST(FrameQueue, AcquireWithoutWaitingGivesNothingAtTheCap) {
    FrameQueue queue(2 * kFrameBytes);
    auto first = queue.acquire(kFrameBytes, /*wait=*/false);
    auto second = queue.acquire(kFrameBytes, /*wait=*/false);
    ASSERT_TRUE(first && second);
    EXPECT_FALSE(queue.acquire(kFrameBytes, /*wait=*/false)) << "the cap is reached: no buffer, no waiting";
    EXPECT_EQ(queue.blockedProducers(), 0u);
    queue.recycle(std::move(*first));
    EXPECT_TRUE(queue.acquire(kFrameBytes, /*wait=*/false)) << "a recycled buffer is given again";
}

TEST(EncoderPool, TryAcquireReportsBusyAndErrorsApart) {
    StalledSink sink;
    EncoderPool pool(sink, 1, 2 * kFrameBytes);
    ASSERT_TRUE(pool.submit(stamped(0, *pool.acquire(kFrameBytes))).ok());
    auto second = pool.tryAcquire(kFrameBytes);
    ASSERT_TRUE(second.ok());
    ASSERT_TRUE(second->has_value());
    auto third = pool.tryAcquire(kFrameBytes);
    ASSERT_TRUE(third.ok()) << "busy is not an error";
    EXPECT_FALSE(third->has_value());
}

namespace {
// A sink whose writes wait at a gate until the test opens it: a stalled encoder, held for as long
// as the test needs to look at the pool.
class GatedSink final : public FrameSink {
public:
    bool ordered() const override { return false; }
    Status write(const CapturedFrame& frame, EncodeScratch&) override {
        std::unique_lock lock(mutex_);
        ++inside;
        opened_.wait(lock, [&] { return open_; });
        --inside;
        frames.push_back(frame.frame);
        return okStatus();
    }
    void open() {
        std::lock_guard lock(mutex_);
        open_ = true;
        opened_.notify_all();
    }
    int writersInside() {
        std::lock_guard lock(mutex_);
        return inside;
    }
    std::vector<int> frames;

private:
    std::mutex mutex_;
    std::condition_variable opened_;
    bool open_ = false;
    int inside = 0;
};
}  // namespace

TEST(EncoderPool, EncodersThatFallBehindGetOneMoreThreadAndMemoryStaysUnderTheCap) {
    GatedSink sink;
    const std::size_t cap = 3 * kFrameBytes;
    EncoderPool pool(sink, /*threads=*/1, cap, /*growTo=*/2);
    constexpr int kFrames = 30;
    std::thread producer([&] {
        for (int f = 0; f < kFrames; ++f) {
            auto buffer = pool.acquire(kFrameBytes);
            ASSERT_TRUE(buffer.ok());
            EXPECT_LE(pool.queue().allocatedBytes(), cap);
            ASSERT_TRUE(pool.submit(stamped(f, std::move(*buffer))).ok());
        }
    });
    // The sink holds every frame: the producer fills the cap, finds no buffer, starts a second
    // encoder (which takes the next frame and waits in the sink too), then waits itself.
    EXPECT_TRUE(eventually([&] { return sink.writersInside() == 2 && pool.queue().blockedProducers() == 1; }));
    EXPECT_EQ(pool.queue().allocatedBytes(), cap);
    sink.open();
    producer.join();
    ASSERT_TRUE(pool.finish().ok());
    EXPECT_EQ(pool.threads(), 2);  // never more than growTo
    EXPECT_EQ(sink.frames.size(), static_cast<std::size_t>(kFrames));
    EXPECT_LE(pool.queue().peakAllocatedBytes(), cap);
}

TEST(EncoderPool, AnOrderedSinkNeverGrowsPastOneThread) {
    RecordingSink sink(/*ordered=*/true, std::chrono::milliseconds(1));
    EncoderPool pool(sink, /*threads=*/1, 2 * kFrameBytes, /*growTo=*/4);
    for (int f = 0; f < 20; ++f) {
        auto buffer = pool.acquire(kFrameBytes);
        ASSERT_TRUE(buffer.ok());
        ASSERT_TRUE(pool.submit(stamped(f, std::move(*buffer))).ok());
    }
    ASSERT_TRUE(pool.finish().ok());
    EXPECT_EQ(pool.threads(), 1);
    std::vector<int> expected(20);
    for (int f = 0; f < 20; ++f) expected[f] = f;
    EXPECT_EQ(sink.frames, expected);
}
