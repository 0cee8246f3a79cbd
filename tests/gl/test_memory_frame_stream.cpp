// The memory frame stream (session/MemoryFrameStream.h) on a SessionCore: frames handed over in
// order with the pixels of their frame, at most inFlight reads and kFramesAhead frames being drawn
// at once, a stop (the consumer's or requested) dropping the reads in flight, and a step's error
// ending the stream.
#include "GlTestSupport.h"

#include <thread>

#include "session/MemoryFrameStream.h"

namespace toyhost::testing {
namespace {

class MemoryFrameStreamTest : public GlTest {
protected:
    // The stream's step: the core's next frame at the fixed step, submitted.
    static MemoryFrameStream::StepFrame stepOf(SessionCore& core) {
        return [&core](int) {
            Status drawn = core.renderFrame(fixedStep(core.frame()), {});
            core.submit();
            return drawn;
        };
    }
    static std::vector<std::uint8_t> bytesOf(const MemoryFrame& frame) {
        const std::size_t bytes = frameBytes(frame.width, frame.height, frame.format);
        return std::vector<std::uint8_t>(reinterpret_cast<const std::uint8_t*>(frame.pixels),
                                         reinterpret_cast<const std::uint8_t*>(frame.pixels) + bytes);
    }
};

TEST_F(MemoryFrameStreamTest, HandsOverTheCapturedFramesInOrderWithinItsBounds) {
    std::unique_ptr<SessionCore> reference = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8);
    std::unique_ptr<SessionCore> core = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8);
    ASSERT_TRUE(reference && core);
    std::vector<std::vector<std::uint8_t>> expected;
    for (int f = 0; f < 12; ++f) {
        stepAt(*reference);
        expected.emplace_back();
        reference->readRgba8(PassId::Image, expected.back());
    }
    Result<std::unique_ptr<MemoryFrameStream>> made = MemoryFrameStream::open(*core, {12, 5, PassId::Image, 2});
    ASSERT_TRUE(made.ok()) << made.error().text();
    MemoryFrameStream& stream = **made;
    std::vector<int> handed;
    auto take = [&](const MemoryFrame& frame) {
        handed.push_back(frame.frame);
        EXPECT_EQ(frame.width, 16);
        EXPECT_EQ(bytesOf(frame), expected[static_cast<std::size_t>(frame.frame)]) << "frame " << frame.frame;
        return true;
    };
    int advances = 0;
    std::size_t mostDrawing = 0;
    int mostReads = 0;
    for (;;) {
        Result<bool> more = stream.advance(stepOf(*core), take);
        ASSERT_TRUE(more.ok()) << more.error().text();
        ++advances;
        mostDrawing = std::max(mostDrawing, stream.framesDrawing());
        mostReads = std::max(mostReads, stream.readsInFlight());
        if (!*more) break;
        ASSERT_LT(advances, 20) << "the stream does not end";
    }
    EXPECT_EQ(handed, (std::vector<int>{0, 5, 10, 11})) << "0, every 5th, and the last, in order";
    EXPECT_EQ(stream.framesRendered(), 12);
    EXPECT_EQ(core->frame(), 12);
    EXPECT_EQ(advances, 12) << "one frame per advance; the last hands the rest over";
    EXPECT_LE(mostDrawing, MemoryFrameStream::kFramesAhead);
    EXPECT_LE(mostReads, 2);
    EXPECT_EQ(stream.readsInFlight(), 0);
}

TEST_F(MemoryFrameStreamTest, AStopDropsTheReadsInFlightAndStepsNothingMore) {
    std::unique_ptr<SessionCore> core = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8);
    ASSERT_TRUE(core);
    // The consumer's false: nothing handed over after it, nothing stepped after that advance.
    Result<std::unique_ptr<MemoryFrameStream>> made = MemoryFrameStream::open(*core, {100, 1, PassId::Image, 3});
    ASSERT_TRUE(made.ok());
    int calls = 0;
    Result<bool> more = true;
    while (more && *more) more = (*made)->advance(stepOf(*core), [&](const MemoryFrame&) { return ++calls < 2; });
    ASSERT_TRUE(more.ok());
    EXPECT_EQ(calls, 2);
    EXPECT_EQ((*made)->readsInFlight(), 0) << "reads dropped";
    EXPECT_FALSE((*made)->holdsGl());
    const int stoppedAt = core->frame();
    EXPECT_FALSE(*(*made)->advance(stepOf(*core), [](const MemoryFrame&) { return true; }));
    EXPECT_EQ(core->frame(), stoppedAt);

    // requestStop() from another thread: what the stream holds (a fence after every frame stepped;
    // reads, when one is still in flight) is dropped, nothing more is stepped or handed over.
    made = MemoryFrameStream::open(*core, {1000, 1, PassId::Image, 3});
    ASSERT_TRUE(made.ok());
    int handed = 0;
    auto count = [&](const MemoryFrame&) { return ++handed > 0; };
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(*(*made)->advance(stepOf(*core), count));
    ASSERT_TRUE((*made)->holdsGl()) << "the last frame's fence";
    const int before = core->frame(), handedBefore = handed;
    std::thread([&] { (*made)->requestStop(); }).join();
    more = (*made)->advance(stepOf(*core), count);
    ASSERT_TRUE(more.ok());
    EXPECT_FALSE(*more);
    EXPECT_EQ(core->frame(), before) << "no frame stepped after the stop";
    EXPECT_EQ(handed, handedBefore) << "no frame handed over after the stop";
    EXPECT_EQ((*made)->readsInFlight(), 0);
    EXPECT_FALSE((*made)->holdsGl()) << "fences dropped with the reads";
}

TEST_F(MemoryFrameStreamTest, AStepsErrorEndsTheStream) {
    std::unique_ptr<SessionCore> core = loadSession(context_, sourceDir() / "shadertoys/pingpong-probe", 16, 8);
    ASSERT_TRUE(core);
    Result<std::unique_ptr<MemoryFrameStream>> made = MemoryFrameStream::open(*core, {10, 1, PassId::Image, 3});
    ASSERT_TRUE(made.ok());
    MemoryFrameStream::StepFrame step = [&](int index) {
        if (index == 2) return Status(Error("the clock broke", Code::Internal));
        return stepOf(*core)(index);
    };
    Result<bool> more = true;
    int advances = 0;
    while (more && *more && ++advances < 10) more = (*made)->advance(step, [](const MemoryFrame&) { return true; });
    ASSERT_FALSE(more.ok());
    EXPECT_NE(more.error().text().find("the clock broke"), std::string::npos);
    EXPECT_EQ((*made)->framesRendered(), 2);
    EXPECT_FALSE((*made)->holdsGl()) << "reads and fences dropped";
}

}  // namespace
}  // namespace toyhost::testing
