// FrameStream without GL, over fake reads that complete when the test says: which frames are
// captured, a frame handed over at the first frame boundary after its read completes (not when
// the bound is reached nor at the next capture), the bound on reads in flight, and a stop.
#include <gtest/gtest.h>

#include <deque>
#include <vector>

#include "capture/FrameStream.h"

using namespace toyhost;

namespace {

// Reads that complete only when complete() says so; handOverOldest() on an incomplete read is a
// wait, counted.
class FakeReads final : public FrameReads {
public:
    int pending() const override { return static_cast<int>(queue.size()); }
    Status start(int frame) override {
        queue.push_back({frame, false});
        return okStatus();
    }
    bool oldestDone() const override { return queue.front().done; }
    Status handOverOldest() override {
        if (!queue.front().done) ++waits;
        handed.push_back(queue.front().frame);
        queue.pop_front();
        return okStatus();
    }
    void dropAll() override {
        dropped += pending();
        queue.clear();
    }
    void completeAll() {
        for (Read& read : queue) read.done = true;
    }

    struct Read {
        int frame;
        bool done;
    };
    std::deque<Read> queue;
    std::vector<int> handed;
    int waits = 0;
    int dropped = 0;
};

TEST(FrameStream, CapturesEveryNthAndTheLast) {
    FrameStream stream({.frames = 301, .every = 100, .inFlight = 3});
    std::vector<int> captured;
    for (int f = 0; f < 301; ++f)
        if (stream.captures(f)) captured.push_back(f);
    EXPECT_EQ(captured, (std::vector<int>{0, 100, 200, 300}));
    FrameStream endless({.frames = 0, .every = 7});
    EXPECT_TRUE(endless.captures(0));
    EXPECT_TRUE(endless.captures(14));
    EXPECT_FALSE(endless.captures(15)) << "no end: no last frame";
    EXPECT_TRUE(FrameStream::captured(4, 5, 3)) << "the last frame";
}

// A stream that starts at iFrame 100 (a render after a seek, or after earlier frames) counts `every`
// on iFrame: it hands over the frames a run from frame 0 would, and its own last one.
TEST(FrameStream, EveryCountsFromTheFirstFramesNumber) {
    FrameStream stream({.frames = 70, .every = 30, .inFlight = 3, .first = 100});
    std::vector<int> captured;
    for (int n = 0; n < 70; ++n)
        if (stream.captures(n)) captured.push_back(100 + n);
    EXPECT_EQ(captured, (std::vector<int>{120, 150, 169}));
    FakeReads reads;
    for (int n = 0; n < 70; ++n) ASSERT_TRUE(stream.rendered(n, reads).ok());
    reads.completeAll();
    ASSERT_TRUE(stream.finish(reads).ok());
    EXPECT_EQ(reads.handed, (std::vector<int>{20, 50, 69})) << "reads are started by the stream's own index";
    FrameStream endless({.frames = 0, .every = 7, .first = 5});
    EXPECT_TRUE(endless.captures(2)) << "iFrame 7";
    EXPECT_FALSE(endless.captures(0)) << "iFrame 5, and no end: no last frame";
}

// render(every=100) gave frame 0 only once frame 100 was read: the stream hands it over at the
// first frame boundary after its read completed.
TEST(FrameStream, AFrameIsHandedOverAtTheFirstBoundaryAfterItsReadCompletes) {
    FrameStream stream({.frames = 301, .every = 100, .inFlight = 3});
    FakeReads reads;
    ASSERT_TRUE(stream.rendered(0, reads).ok());
    EXPECT_TRUE(reads.handed.empty()) << "its read is not complete yet";
    ASSERT_TRUE(stream.rendered(1, reads).ok());
    EXPECT_TRUE(reads.handed.empty());
    reads.completeAll();  // the GPU finished frame 0's read while frame 2 was being submitted
    ASSERT_TRUE(stream.rendered(2, reads).ok());
    EXPECT_EQ(reads.handed, std::vector<int>{0}) << "handed over after frame 2, not after frame 100";
    EXPECT_EQ(reads.waits, 0);
    // From here each read completes while the next frame is submitted.
    for (int f = 3; f < 301; ++f) {
        reads.completeAll();
        ASSERT_TRUE(stream.rendered(f, reads).ok());
        if (f == 101) EXPECT_EQ(reads.handed, (std::vector<int>{0, 100})) << "frame 100, after frame 101";
    }
    ASSERT_TRUE(stream.finish(reads).ok());
    EXPECT_EQ(reads.handed, (std::vector<int>{0, 100, 200, 300}));
    EXPECT_EQ(reads.waits, 1) << "only the last read, at the end";
}

TEST(FrameStream, AtMostInFlightReadsWaitTheOldestIsWaitedForFirst) {
    FrameStream stream({.frames = 10, .every = 1, .inFlight = 3});
    FakeReads reads;
    for (int f = 0; f < 3; ++f) ASSERT_TRUE(stream.rendered(f, reads).ok());
    EXPECT_EQ(reads.pending(), 3);
    EXPECT_EQ(reads.waits, 0);
    ASSERT_TRUE(stream.rendered(3, reads).ok());
    EXPECT_EQ(reads.pending(), 3) << "the bound holds";
    EXPECT_EQ(reads.handed, std::vector<int>{0});
    EXPECT_EQ(reads.waits, 1) << "frame 0's read was waited for, before frame 3's started";
}

TEST(FrameStream, AfterAStopNothingIsHandedOverAndFinishDrops) {
    FrameStream stream({.frames = 10, .every = 1, .inFlight = 3});
    FakeReads reads;
    ASSERT_TRUE(stream.rendered(0, reads).ok());
    ASSERT_TRUE(stream.rendered(1, reads).ok());
    reads.completeAll();
    stream.requestStop();
    EXPECT_TRUE(stream.stopRequested());
    ASSERT_TRUE(stream.rendered(2, reads).ok());
    EXPECT_TRUE(reads.handed.empty());
    EXPECT_EQ(reads.pending(), 2) << "frame 2 was not read";
    ASSERT_TRUE(stream.finish(reads).ok());
    EXPECT_EQ(reads.dropped, 2);
    EXPECT_TRUE(reads.handed.empty());
}

// A consumer that asks for a stop while a frame is handed over gets no further frame.
TEST(FrameStream, AStopAskedDuringAHandOverEndsTheHandingOver) {
    FrameStream stream({.frames = 10, .every = 1, .inFlight = 3});
    class Stopping final : public FrameReads {
    public:
        explicit Stopping(FrameStream& s) : stream(s) {}
        int pending() const override { return inner.pending(); }
        Status start(int frame) override { return inner.start(frame); }
        bool oldestDone() const override { return true; }
        Status handOverOldest() override {
            stream.requestStop();
            inner.completeAll();
            return inner.handOverOldest();
        }
        void dropAll() override { inner.dropAll(); }
        FrameStream& stream;
        FakeReads inner;
    } reads(stream);
    ASSERT_TRUE(stream.rendered(0, reads.inner).ok());
    ASSERT_TRUE(stream.rendered(1, reads.inner).ok());
    ASSERT_TRUE(stream.poll(reads).ok());
    EXPECT_EQ(reads.inner.handed, std::vector<int>{0});
    EXPECT_EQ(reads.pending(), 1);
}

}  // namespace
