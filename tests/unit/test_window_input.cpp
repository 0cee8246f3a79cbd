// Window input as the site computes it (iMouse pixel position, JavaScript keyCodes), the control
// keys window mode keeps, and the real-time clock (pause, step, restart, fixed step).
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "input/WindowControls.h"
#include "input/WindowInput.h"
#include "timing/FrameClock.h"
#include "timing/ProgressLine.h"
#include "timing/RealTimeClock.h"

using namespace toyhost;

TEST(WindowInput, MousePositionIsFlooredCanvasPixelsFromTheBottom) {
    // Same size: y flips around the canvas height, as the site's floor(h - y / rectH * h).
    EXPECT_EQ(siteMousePosition(50, 30, 200, 100, 200, 100), glm::vec2(50, 70));
    EXPECT_EQ(siteMousePosition(0, 0, 200, 100, 200, 100), glm::vec2(0, 100)) << "top-left corner";
    EXPECT_EQ(siteMousePosition(199.6, 99.6, 200, 100, 200, 100), glm::vec2(199, 0));
    // HiDPI: window coordinates are half the framebuffer pixels.
    EXPECT_EQ(siteMousePosition(50.25, 30, 200, 100, 400, 200), glm::vec2(100, 140));
    EXPECT_EQ(siteMousePosition(1, 1, 0, 0, 400, 200), glm::vec2(0, 0)) << "a minimised window";
}

TEST(WindowInput, KeysBecomeTheBrowsersKeyCodes) {
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_A), 65);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_Z), 90);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_0), 48);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_SPACE), 32);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_LEFT), 37);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_UP), 38);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_RIGHT), 39);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_DOWN), 40);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_ENTER), 13);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_KP_ENTER), 13);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_ESCAPE), 27);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_TAB), 9);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_BACKSPACE), 8);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_LEFT_SHIFT), 16);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_RIGHT_SHIFT), 16);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_LEFT_CONTROL), 17);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_RIGHT_ALT), 18);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_F1), 112);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_F12), 123);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_KP_0), 96);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_KP_9), 105);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_KP_ADD), 107);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_SEMICOLON), 186);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_EQUAL), 187);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_COMMA), 188);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_MINUS), 189);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_PERIOD), 190);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_SLASH), 191);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_GRAVE_ACCENT), 192);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_LEFT_BRACKET), 219);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_BACKSLASH), 220);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_RIGHT_BRACKET), 221);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_APOSTROPHE), 222);
    EXPECT_EQ(javascriptKeyCode(GLFW_KEY_WORLD_1), 0);
    for (int key = GLFW_KEY_SPACE; key <= GLFW_KEY_LAST; ++key) EXPECT_LT(javascriptKeyCode(key), 256) << key;
}

TEST(WindowControls, OnlyTheDocumentedKeysAreKept) {
    EXPECT_EQ(controlForKey(GLFW_KEY_F1, 0), Control::Help);
    EXPECT_EQ(controlForKey(GLFW_KEY_F2, 0), Control::Inspector);
    EXPECT_EQ(controlForKey(GLFW_KEY_F5, 0), Control::Restart);
    EXPECT_EQ(controlForKey(GLFW_KEY_R, GLFW_MOD_CONTROL), Control::Restart);
    EXPECT_EQ(controlForKey(GLFW_KEY_R, 0), Control::None) << "R alone is the shader's";
    EXPECT_EQ(controlForKey(GLFW_KEY_F6, 0), Control::Pause);
    EXPECT_EQ(controlForKey(GLFW_KEY_PAUSE, 0), Control::Pause);
    EXPECT_EQ(controlForKey(GLFW_KEY_F7, 0), Control::Step);
    EXPECT_EQ(controlForKey(GLFW_KEY_F11, 0), Control::Fullscreen);
    EXPECT_EQ(controlForKey(GLFW_KEY_F12, 0), Control::Screenshot);
    EXPECT_EQ(controlForKey(GLFW_KEY_ESCAPE, 0), Control::Quit);
    EXPECT_EQ(controlForKey(GLFW_KEY_Q, GLFW_MOD_CONTROL), Control::Quit);
    for (int key : {GLFW_KEY_SPACE, GLFW_KEY_A, GLFW_KEY_Q, GLFW_KEY_LEFT, GLFW_KEY_ENTER, GLFW_KEY_F3, GLFW_KEY_TAB, GLFW_KEY_1})
        EXPECT_EQ(controlForKey(key, 0), Control::None) << key;
}

TEST(RealTimeClock, RealTimeFollowsTheClockMinusPauses) {
    RealTimeClock clock(RealTimeClockOptions{}, 100.0);
    FrameTime t = clock.frame(100.0, 0);
    EXPECT_DOUBLE_EQ(t.time, 0.0);
    EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 60.0) << "the first frame has the nominal delta";
    t = clock.frame(100.02, 0);
    EXPECT_NEAR(t.time, 0.02, 1e-9);
    EXPECT_NEAR(t.timeDelta, 0.02, 1e-9);
    EXPECT_DOUBLE_EQ(t.frameRate, 60.0) << "the site's counter says 60 until half a second has passed";
    clock.setPaused(true, 100.05);
    EXPECT_FALSE(clock.shouldRender());
    clock.setPaused(false, 105.05);  // five seconds paused do not count
    EXPECT_TRUE(clock.shouldRender());
    t = clock.frame(105.06, 0);
    EXPECT_NEAR(t.time, 0.06, 1e-9);
    EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 60.0) << "first frame after a pause";
}

// iFrameRate is piLibs' FPS counter, as the site's render loop counts before each Paint: 60 until
// more than 0.5 s passed since the player started, then frames / seconds of each closed window.
TEST(RealTimeClock, FrameRateIsTheSitesHalfSecondCounter) {
    RealTimeClock clock(RealTimeClockOptions{}, 100.0);
    double rate = 0;
    int changes = 0;
    for (int k = 0; k <= 26; ++k) {
        rate = clock.frame(100.0 + 0.02 * k, 0).frameRate;
        if (k < 26) EXPECT_DOUBLE_EQ(rate, 60.0) << k;
    }
    EXPECT_NEAR(rate, 27 / 0.52, 1e-9) << "27 frames counted in the first window of 0.52 s";
    ASSERT_TRUE(clock.measuredFrameRate());
    EXPECT_NEAR(*clock.measuredFrameRate(), 27 / 0.52, 1e-9);
    for (int k = 27; k <= 52; ++k) {
        const double next = clock.frame(100.0 + 0.02 * k, 0).frameRate;
        changes += next != rate;
        rate = next;
    }
    EXPECT_EQ(changes, 1);
    EXPECT_NEAR(rate, 26 / 0.52, 1e-9);
    // A restart does not reset the counter (the site resets it only when the player starts).
    clock.restart(101.05);
    EXPECT_NEAR(clock.frame(101.06, 0).frameRate, 26 / 0.52, 1e-9);
    RealTimeClock fresh(RealTimeClockOptions{}, 0.0);
    EXPECT_FALSE(fresh.measuredFrameRate()) << "nothing measured before the first window closes";
}

TEST(RealTimeClock, InputOrARestartWhilePausedForcesOneFrameAtThePausedTime) {
    RealTimeClock clock(RealTimeClockOptions{}, 0.0);
    clock.frame(0.0, 0);
    clock.frame(0.4, 0);
    clock.setPaused(true, 0.5);
    EXPECT_FALSE(clock.shouldRender());
    clock.forceFrame();
    ASSERT_TRUE(clock.shouldRender());
    FrameTime t = clock.frame(3.0, 0);
    EXPECT_DOUBLE_EQ(t.time, 0.4) << "the paused time, as the site paints mTf";
    EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 60.0);
    EXPECT_FALSE(clock.shouldRender());
    clock.restart(4.0);
    ASSERT_TRUE(clock.shouldRender()) << "a restart while paused shows the restarted frame";
    t = clock.frame(4.5, 0);
    EXPECT_DOUBLE_EQ(t.time, 0.0);
    EXPECT_FALSE(clock.shouldRender());
    clock.forceFrame();
    clock.setPaused(false, 5.0);
    clock.forceFrame();
    EXPECT_TRUE(clock.shouldRender());
    EXPECT_NEAR(clock.frame(5.25, 0).time, 0.25, 1e-9) << "not paused: forcing changes nothing";
}

TEST(RealTimeClock, ARepaintWhilePausedIsAtThePausedTimeAndLeavesTheClockAlone) {
    RealTimeClock clock(RealTimeClockOptions{}, 0.0);
    clock.frame(0.0, 0);
    clock.frame(0.4, 0);
    clock.setPaused(true, 0.5);
    clock.stepOnce();
    FrameTime t = clock.repaint(3.0, 0);
    EXPECT_DOUBLE_EQ(t.time, 0.4) << "the shown frame's time";
    EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 60.0) << "as the site paints a frame forced while paused";
    EXPECT_TRUE(clock.shouldRender()) << "the pending step stays pending";
    EXPECT_NEAR(clock.frame(4.0, 0).time, 0.4 + 1.0 / 60.0, 1e-9) << "and steps from the paused time";
    EXPECT_FALSE(clock.shouldRender());
    t = clock.repaint(5.0, 0);
    EXPECT_NEAR(t.time, 0.4 + 1.0 / 60.0, 1e-9) << "a repaint does not move the time";
    EXPECT_NEAR(clock.repaint(6.0, 0).time, t.time, 1e-12);
    EXPECT_FALSE(clock.shouldRender()) << "a repaint forces no frame";
    clock.setPaused(false, 7.0);
    EXPECT_NEAR(clock.frame(7.25, 0).time, 0.5 + 1.0 / 60.0 + 0.25, 1e-9) << "repaints take no time from the run";

    RealTimeClockOptions fixed;
    fixed.fixedFps = 30.0;
    RealTimeClock stepped(fixed, 0.0);
    stepped.frame(0.0, 0);
    stepped.frame(0.0, 0);
    stepped.setPaused(true, 1.0);
    t = stepped.repaint(2.0, 0);
    EXPECT_DOUBLE_EQ(t.time, 1.0 / 30.0);
    EXPECT_DOUBLE_EQ(t.frameRate, 30.0);
    stepped.setPaused(false, 3.0);
    EXPECT_DOUBLE_EQ(stepped.frame(3.0, 0).time, 2.0 / 30.0) << "the repaint was not a step";
}

TEST(RealTimeClock, StepWhilePausedRendersExactlyOneFrame) {
    RealTimeClock clock(RealTimeClockOptions{}, 0.0);
    clock.frame(0.5, 0);
    clock.setPaused(true, 0.5);
    clock.stepOnce();
    EXPECT_TRUE(clock.shouldRender());
    const FrameTime t = clock.frame(9.0, 0);
    EXPECT_NEAR(t.time, 0.5 + 1.0 / 60.0, 1e-9) << "one nominal frame later, not the wall time";
    EXPECT_FALSE(clock.shouldRender());
    clock.setPaused(false, 10.0);
    EXPECT_NEAR(clock.frame(10.0, 0).time, 0.5 + 1.0 / 60.0, 1e-9) << "resumes where the step left it";
}

TEST(RealTimeClock, FixedStepIgnoresTheWallClockAndRestartGoesBackToTheStart) {
    RealTimeClockOptions options;
    options.fixedFps = 30.0;
    options.startTime = 2.0;
    RealTimeClock clock(options, 0.0);
    for (int n = 0; n < 3; ++n) {
        const FrameTime t = clock.frame(1000.0 * n, 0);
        EXPECT_DOUBLE_EQ(t.time, 2.0 + n / 30.0);
        EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 30.0);
        EXPECT_DOUBLE_EQ(t.frameRate, 30.0);
    }
    clock.restart(5000.0);
    EXPECT_DOUBLE_EQ(clock.frame(5000.5, 0).time, 2.0);
    RealTimeClock real(RealTimeClockOptions{}, 0.0);
    real.frame(3.0, 0);
    real.restart(7.0);
    const FrameTime t = real.frame(7.25, 0);
    EXPECT_NEAR(t.time, 0.25, 1e-9);
    EXPECT_DOUBLE_EQ(t.timeDelta, 1.0 / 60.0);
}

TEST(RealTimeClock, DateIsTheGivenWallClock) {
    RealTimeClock clock(RealTimeClockOptions{}, 0.0);
    Result<double> wall = parseWallClock("2026-11-22T10:00:30");
    ASSERT_TRUE(wall.ok());
    EXPECT_EQ(clock.frame(0.0, *wall).date, glm::vec4(2026, 10, 22, 36030));
}
