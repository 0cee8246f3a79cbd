// A window's title (timing/WindowTitle): the rate frames are shown at with one decimal, none while
// paused, the first reading after a pause measured without the paused time, and "stopping" after
// Esc. Times are made up: the rate is pure arithmetic on the times passed in.
#include <gtest/gtest.h>

#include "timing/WindowTitle.h"

using namespace toyhost;

TEST(WindowTitle, SaysTheRateWithOneDecimalTheShownFrameAndTheState) {
    EXPECT_EQ(formatWindowTitle({"ocean", std::nullopt, -1, 0, false, ""}), "ocean");
    EXPECT_EQ(formatWindowTitle({"ocean", std::nullopt, 0, 0, false, ""}), "ocean | -- fps | iFrame 0 | iTime 0.00");
    // A slow shader is not "0 fps".
    EXPECT_EQ(formatWindowTitle({"ocean", 0.1, 2, 20.0, false, ""}), "ocean | 0.1 fps | iFrame 2 | iTime 20.00");
    EXPECT_EQ(formatWindowTitle({"", 59.64, 3, 0.05, false, "image.glsl:3:1: error: x"}),
              "toyhost | 59.6 fps | iFrame 3 | iTime 0.05 | image.glsl:3:1: error: x");
    // Paused: nothing is rendered, so no rate (not the last one, gone stale).
    EXPECT_EQ(formatWindowTitle({"ocean", 0.8, 12, 15.0, true, ""}), "ocean | iFrame 12 | iTime 15.00 | paused (F6)");
}

TEST(WindowTitle, SaysStoppingWhileTheGracePeriodRuns) {
    WindowTitle title{"ocean", 60.0, 12, 0.2, false, ""};
    title.stopping = true;
    EXPECT_EQ(formatWindowTitle(title), "ocean | 60.0 fps | iFrame 12 | iTime 0.20 | stopping (Esc again: at once)");
    title.paused = true;
    EXPECT_EQ(formatWindowTitle(title), "ocean | iFrame 12 | iTime 0.20 | stopping (Esc again: at once)");
}

TEST(ShownFrameRate, CountsFramesOverWindowsOfHalfASecond) {
    ShownFrameRate rate(100.0);
    for (int i = 1; i <= 30; ++i) rate.frame(100.0 + i / 100.0);  // 100 fps for 0.3 s
    EXPECT_FALSE(rate.rate()) << "not measured until half a second has passed";
    for (int i = 31; i <= 60; ++i) rate.frame(100.0 + i / 100.0);
    ASSERT_TRUE(rate.rate());
    EXPECT_NEAR(*rate.rate(), 100.0, 0.5);
    // A slow shader: one frame every 10 s reads 0.1.
    ShownFrameRate slow(0.0);
    slow.frame(10.0);
    ASSERT_TRUE(slow.rate());
    EXPECT_DOUBLE_EQ(*slow.rate(), 0.1);
}

// The case: ~300 fps, paused for several seconds inside a window of the counter; the first
// reading after the pause read 14 fps because the paused time counted.
TEST(ShownFrameRate, APauseIsLeftOutOfTheFirstReadingAfterIt) {
    ShownFrameRate rate(0.0);
    double t = 0;
    for (int i = 0; i < 300; ++i) rate.frame(t += 1.0 / 300.0);  // 1 s at 300 fps
    for (int i = 0; i < 60; ++i) rate.frame(t += 1.0 / 300.0);   // 0.2 s into the next window
    rate.setPaused(true, t);
    EXPECT_FALSE(rate.rate()) << "no rate while paused";
    rate.frame(t + 1.0);  // a frame forced by input while paused does not count
    t += 10.0;
    rate.setPaused(false, t);
    for (int i = 0; i < 95; ++i) rate.frame(t += 1.0 / 300.0);  // the window closes 0.5 s of running later
    ASSERT_TRUE(rate.rate());
    EXPECT_NEAR(*rate.rate(), 300.0, 3.0);
}
