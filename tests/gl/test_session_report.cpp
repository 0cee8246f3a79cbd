// The summary every command prints after a run (session/SessionReport.cpp): start-up, the first
// frame and the steady rate kept apart, what was written (files, stdout, a checkpoint) or that
// nothing was.
#include "GlTestSupport.h"

#include "session/RoundClock.h"
#include "session/SessionObserver.h"

#include <chrono>

namespace toyhost::testing {
namespace {

SessionReport report() {
    SessionReport r;
    r.name = "ocean";
    r.context = "EGL surfaceless";
    r.mode = "headless";
    r.width = 640;
    r.height = 360;
    return r;
}

TEST(SessionReport, SeparatesStartUpTheFirstFrameAndTheSteadyRate) {
    SessionReport r = report();
    r.frames = 61;
    r.startupSeconds = 0.2211;
    r.firstFrameSeconds = 3.159;
    r.restSeconds = 12.0;
    const std::vector<std::string> lines = summaryLines(r);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines[0],
              "ocean: 61 frames at 640x360, headless on EGL surfaceless: start-up 221.1 ms, first frame 3.159 s, then 60 "
              "frames in 12.000 s (5.0 frames/s, 200.0 ms/frame)");
    r.frames = 1;
    EXPECT_EQ(summaryLines(r)[0], "ocean: 1 frame at 640x360, headless on EGL surfaceless: start-up 221.1 ms, first frame 3.159 s");
}

// Issue 43: a window paused for 40 s during a 1 s run said "0.4 frames/s". The pause is left out of
// the frames' time (RoundClock) and said apart; a paced wait for the next frame is frame time.
TEST(SessionReport, PausedTimeIsNotFrameTime) {
    using Clock = RoundClock::Clock;
    RoundClock clock;
    clock.beginRound();
    (void)clock.frameStarting();
    clock.idled(Clock::now(), Clock::now() + std::chrono::seconds(100));  // before the first frame: start-up
    clock.frameDone();
    const Clock::time_point from = Clock::now();
    clock.idled(from, from + std::chrono::seconds(40));
    clock.idle(false, [] {});  // a paced wait: counted as the frames' time (nothing to add here)
    for (int n = 0; n < 10; ++n) clock.frameDone();
    SessionReport r = report();
    r.frames = clock.frames();
    clock.fill(r, from + std::chrono::seconds(42));
    EXPECT_NEAR(r.pausedSeconds, 40.0, 1e-9);
    EXPECT_NEAR(r.restSeconds, 2.0, 0.5) << "42 s since the first frame, 40 of them paused";
    r.firstFrameSeconds = 0.5;
    r.restSeconds = 2.0;
    r.startupSeconds = 0.1;
    EXPECT_EQ(summaryLines(r)[0],
              "ocean: 11 frames at 640x360, headless on EGL surfaceless: start-up 100.0 ms, first frame 500.0 ms, then 10 "
              "frames in 2.000 s (5.0 frames/s, 200.0 ms/frame; 40.000 s paused, not counted)");
    clock.beginRound();
    (void)clock.frameStarting();
    clock.frameDone();
    SessionReport next = report();
    clock.fill(next);
    EXPECT_EQ(next.pausedSeconds, 0.0) << "a new round starts its pauses over";
}

TEST(SessionReport, SaysWhatWasWrittenIncludingACheckpoint) {
    SessionReport r = report();
    r.frames = 3;
    r.files = {"out/f_0.png", "out/f_1.png", "out/f_2.png"};
    r.bytesWritten = 3 * 1024;
    r.outputAsked = true;
    EXPECT_EQ(summaryLines(r)[1], "wrote 3 files (3.0 KiB): out/f_0.png .. out/f_2.png");
    SessionReport none = report();
    none.frames = 3;
    EXPECT_EQ(summaryLines(none).back(), "no files written (no --out; e.g. --out frame_%04d.png captures the frames)");
    none.checkpoint = "state.ckpt";
    const std::vector<std::string> lines = summaryLines(none);
    EXPECT_EQ(lines[1], "checkpoint written: state.ckpt");
    EXPECT_EQ(lines[2], "no frames written (no --out; e.g. --out frame_%04d.png captures the frames)");
    SessionReport window = report();
    window.interactive = true;
    EXPECT_EQ(summaryLines(window).size(), 1u) << "a window without --out is the normal case";
}

TEST(SessionReport, ACheckpointOnlyRunSaysItWroteTheCheckpoint) {
    const auto dir = freshOutputDir("session-report");
    auto run = runToyhost("run " + (sourceDir() / "shadertoys/pingpong-probe").string() + " --size 16x8 --frames 4 --checkpoint " +
                          (dir / "state.ckpt").string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("checkpoint written: " + (dir / "state.ckpt").string()), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("no frames written"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("no files written"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace toyhost::testing
