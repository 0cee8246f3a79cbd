// FramePacer (timing/FramePacer.h): a window with --fps F draws F frames per second of wall time,
// checked with a made-up clock: the waits it asks for, no burst after a slow frame, no catching up
// after a pause.
#include <gtest/gtest.h>

#include "timing/FramePacer.h"

using namespace toyhost;

TEST(FramePacer, DrawsFFramesPerSecondOfWallTime) {
    FramePacer pacer(10.0);
    double now = 100.0;
    int frames = 0;
    // A renderer that takes 1 ms per frame and sleeps exactly as long as it is asked.
    while (now < 101.95) {  // frames due at 100.0, 100.1, ..., 101.9
        if (const double wait = pacer.wait(now); wait > 0) {
            now += wait;
            continue;
        }
        pacer.drawn(now);
        ++frames;
        now += 0.001;
    }
    EXPECT_EQ(frames, 20);  // 2 s at 10 fps
    EXPECT_GE(now, 101.9);
}

TEST(FramePacer, TheFirstFrameIsDueAtOnceAndTheNextOnePeriodLater) {
    FramePacer pacer(4.0);
    EXPECT_EQ(pacer.wait(5.0), 0.0);
    pacer.drawn(5.0);
    EXPECT_NEAR(pacer.wait(5.0), 0.25, 1e-9);
    EXPECT_NEAR(pacer.wait(5.1), 0.15, 1e-9);
    EXPECT_EQ(pacer.wait(5.25), 0.0);
}

TEST(FramePacer, WaitsThatOvershootDoNotLowerTheRate) {
    FramePacer pacer(10.0);
    double now = 0;
    pacer.drawn(now);
    // Every wait ends 20 ms late (a coarse timer): the schedule stays on 0.1, 0.2, ...
    for (int i = 1; i <= 10; ++i) {
        now += pacer.wait(now) + 0.02;
        pacer.drawn(now);
    }
    EXPECT_NEAR(now, 1.0 + 0.02, 1e-9);
}

TEST(FramePacer, ASlowFrameRestartsTheScheduleInsteadOfABurst) {
    FramePacer pacer(10.0);
    pacer.drawn(0.0);
    pacer.drawn(0.1);
    pacer.drawn(1.0);  // 0.7 s late: four frames behind
    EXPECT_NEAR(pacer.wait(1.0), 0.1, 1e-9) << "the next is one period later, not at once";
}

TEST(FramePacer, AfterAResetTheNextFrameIsDueAtOnce) {
    FramePacer pacer(2.0);
    pacer.drawn(0.0);
    EXPECT_NEAR(pacer.wait(0.1), 0.4, 1e-9);
    pacer.reset();
    EXPECT_EQ(pacer.wait(0.1), 0.0);
    pacer.drawn(0.1);
    EXPECT_NEAR(pacer.wait(0.1), 0.5, 1e-9);
}
