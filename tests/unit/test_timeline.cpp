// Timeline (timing/Timeline.h): the one fixed-step input of every headless loop: frame n's clock,
// the iDate that follows iTime (the rule the window's clock shares), sub-frame times, and the
// scripted events due before each frame, replayed and dropped when the run jumps forward.
#include <gtest/gtest.h>

#include <vector>

#include "input/InputScript.h"
#include "timing/FrameClock.h"
#include "timing/RealTimeClock.h"
#include "timing/Timeline.h"

namespace toyhost {
namespace {

double wallClock(const char* text) {
    Result<double> parsed = parseWallClock(text);
    EXPECT_TRUE(parsed.ok());
    return parsed ? *parsed : 0.0;
}

TimelineDesc scripted(double fps = 60.0) {
    TimelineDesc desc;
    desc.fps = fps;
    desc.startTime = 2.0;
    desc.wallClockStart = wallClock("2024-02-29T23:59:59");
    Result<MouseScript> mouse = parseMouseScript(
        R"([{"frame": 1, "type": "down", "x": 10, "y": 20}, {"time": 2.05, "type": "move", "x": 30, "y": 40},
            {"frame": 5, "type": "up"}])",
        "mouse.json");
    EXPECT_TRUE(mouse.ok()) << mouse.error().text();
    Result<KeyScript> keys = parseKeyScript(R"([{"frame": 2, "type": "tap", "key": 65}])", "keys.json");
    EXPECT_TRUE(keys.ok()) << keys.error().text();
    desc.mouse = std::move(*mouse);
    desc.keys = std::move(*keys);
    return desc;
}

TEST(Timeline, FrameClockIsStartPlusFrameOverFps) {
    const Timeline t(scripted(50.0));
    const FrameTime f = t.at(10);
    EXPECT_DOUBLE_EQ(f.time, 2.0 + 10 / 50.0);
    EXPECT_DOUBLE_EQ(f.timeDelta, 1 / 50.0);
    EXPECT_DOUBLE_EQ(f.frameRate, 50.0);
    // The same numbers as the fixed-step clock on its own (what every run used before).
    const FrameClock clock(50.0, 2.0, wallClock("2024-02-29T23:59:59"));
    EXPECT_EQ(f.time, clock.time(10));
    EXPECT_EQ(f.date, clock.date(10));
}

TEST(Timeline, SubFrameTimesMoveITimeAndIDateButNotTheStep) {
    const Timeline t(scripted(10.0));
    const FrameTime quarter = t.at(3, 0.25);
    EXPECT_DOUBLE_EQ(quarter.time, 2.0 + 3.25 / 10.0);
    EXPECT_DOUBLE_EQ(quarter.timeDelta, 0.1);
    EXPECT_DOUBLE_EQ(quarter.frameRate, 10.0);
    // iDate: 23:59:59 at iTime 2.0, so 0.325 s later.
    EXPECT_FLOAT_EQ(quarter.date.w, 86399.0f + 0.325f);
    EXPECT_EQ(t.at(3, 0.0).time, t.at(3).time);
}

TEST(Timeline, DateRollsOverMidnightAtTheRightITime) {
    const Timeline t(scripted(1.0));
    // Leap day 23:59:59 at frame 0; frame 1 is 1 March 00:00:00.
    EXPECT_EQ(t.at(0).date, glm::vec4(2024, 1, 29, 86399));
    EXPECT_EQ(t.at(1).date, glm::vec4(2024, 2, 1, 0));
}

TEST(Timeline, ATimeGivenByTheCallerGetsTheSameDateRule) {
    const Timeline t(scripted(60.0));
    const FrameTime f = t.atTime(2.5, 0.02, 50.0);
    EXPECT_DOUBLE_EQ(f.time, 2.5);
    EXPECT_DOUBLE_EQ(f.timeDelta, 0.02);
    EXPECT_DOUBLE_EQ(f.frameRate, 50.0);
    EXPECT_EQ(f.date, dateOfTime(t.wallClockStart(), 2.0, 2.5));
}

TEST(Timeline, WindowClockWithAFixedStepHasTheTimelinesDates) {
    // A window with --fps and --date: the real-time clock's iDate follows iTime by the same rule.
    const TimelineDesc desc = scripted(30.0);
    const Timeline t(desc);
    RealTimeClockOptions options;
    options.fixedFps = 30.0;
    options.startTime = desc.startTime;
    options.wallClockStart = desc.wallClockStart;
    RealTimeClock window(options, 100.0);
    for (int n = 0; n < 5; ++n) {
        const FrameTime w = window.frame(100.0 + n * 0.5, /*wallClock=*/0.0);
        EXPECT_EQ(w.time, t.at(n).time) << n;
        EXPECT_EQ(w.date, t.at(n).date) << n;
    }
}

using Type = InputEvent::Type;

std::vector<std::vector<InputEvent>> eventsPerFrame(Timeline& t, int from, int to) {
    std::vector<std::vector<InputEvent>> frames;
    for (int n = from; n < to; ++n) {
        std::vector<InputEvent> events;
        t.next(n, events);
        frames.push_back(events);
    }
    return frames;
}

TEST(Timeline, ScriptedEventsComeBeforeTheirFrameInOrder) {
    Timeline t(scripted(60.0));
    const auto frames = eventsPerFrame(t, 0, 7);
    EXPECT_TRUE(frames[0].empty());
    ASSERT_EQ(frames[1].size(), 1u);
    EXPECT_EQ(frames[1][0].type, Type::MouseDown);
    // Frame 2: the key tap goes down; frame 3 (iTime 2.05) the timed move and the tap's release.
    ASSERT_EQ(frames[2].size(), 1u);
    EXPECT_EQ(frames[2][0].type, Type::KeyDown);
    ASSERT_EQ(frames[3].size(), 2u);
    EXPECT_EQ(frames[3][0].type, Type::MouseMove);
    EXPECT_EQ(frames[3][1].type, Type::KeyUp);
    ASSERT_EQ(frames[5].size(), 1u);
    EXPECT_EQ(frames[5][0].type, Type::MouseUp);
    EXPECT_TRUE(frames[6].empty());
}

TEST(Timeline, AJumpForwardDropsTheSkippedFramesEvents) {
    Timeline t(scripted(60.0));
    std::vector<InputEvent> events;
    t.next(4, events);  // a run resumed at frame 4: frames 0-3's events are in its saved state
    EXPECT_TRUE(events.empty());
    t.next(5, events);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].type, Type::MouseUp);
}

TEST(Timeline, RestartReplaysTheScriptsFromFrameZero) {
    Timeline t(scripted(60.0));
    const auto first = eventsPerFrame(t, 0, 7);
    t.restart();
    const auto again = eventsPerFrame(t, 0, 7);
    ASSERT_EQ(first.size(), again.size());
    for (std::size_t n = 0; n < first.size(); ++n) EXPECT_EQ(first[n], again[n]) << "frame " << n;
}

}  // namespace
}  // namespace toyhost
