// iMouse rules (SEMANTICS.md "iMouse"), checked on MouseState directly and frame by frame
// through a MouseScriptPlayer.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "input/MouseState.h"

namespace glm {
inline void PrintTo(const vec4& v, std::ostream* os) {
    *os << "(" << v.x << ", " << v.y << ", " << v.z << ", " << v.w << ")";
}
}  // namespace glm

namespace toyhost {
namespace {

using glm::vec4;

// Runs `json` as a mouse script for `frames` frames at `fps` and returns iMouse of every frame.
std::vector<vec4> iMouseFrames(const std::string& json, int frames, double fps = 60.0) {
    auto script = parseMouseScript(json, "test.json");
    EXPECT_TRUE(script.ok()) << script.error().text();
    MouseScriptPlayer player(std::move(*script));
    MouseState mouse;
    std::vector<vec4> out;
    for (int f = 0; f < frames; ++f) {
        player.applyBeforeFrame(f, f / fps, mouse);
        out.push_back(mouse.uniform());
        mouse.endFrame();
    }
    return out;
}

TEST(MouseState, AllZeroBeforeAnyClick) {
    MouseState mouse;
    EXPECT_EQ(mouse.uniform(), vec4(0));
    mouse.move(50, 60);  // hover without a button: not seen
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(0));
    EXPECT_FALSE(mouse.held());
}

TEST(MouseState, PressSetsPositionAndOriginWithClickSignal) {
    MouseState mouse;
    mouse.press(120, 80);
    EXPECT_TRUE(mouse.held());
    EXPECT_EQ(mouse.uniform(), vec4(120, 80, 120, 80));
}

TEST(MouseState, ClickSignalLastsOneFrame) {
    MouseState mouse;
    mouse.press(120, 80);
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(120, 80, 120, -80));
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(120, 80, 120, -80));
}

TEST(MouseState, DragMovesXYOnly) {
    MouseState mouse;
    mouse.press(120, 80);
    mouse.endFrame();
    mouse.move(130, 90);
    EXPECT_EQ(mouse.uniform(), vec4(130, 90, 120, -80));
}

TEST(MouseState, ReleaseNegatesZAndKeepsLastDraggedPosition) {
    MouseState mouse;
    mouse.press(120, 80);
    mouse.move(130, 90);
    mouse.endFrame();
    mouse.release();
    EXPECT_FALSE(mouse.held());
    EXPECT_EQ(mouse.uniform(), vec4(130, 90, -120, -80));
    mouse.move(300, 300);  // not held: ignored
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(130, 90, -120, -80));
}

TEST(MouseState, PressAndReleaseInOneFrameKeepClickSignalButZIsNegative) {
    MouseState mouse;
    mouse.press(10, 20);
    mouse.release();
    EXPECT_EQ(mouse.uniform(), vec4(10, 20, -10, 20));
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(10, 20, -10, -20));
}

TEST(MouseState, SecondClickStartsANewClick) {
    MouseState mouse;
    mouse.press(10, 20);
    mouse.endFrame();
    mouse.release();
    mouse.endFrame();
    mouse.press(200, 100);
    EXPECT_EQ(mouse.uniform(), vec4(200, 100, 200, 100));
    mouse.endFrame();
    EXPECT_EQ(mouse.uniform(), vec4(200, 100, 200, -100));
}

TEST(MouseScriptPlayer, PressDragReleaseSecondClickFrameByFrame) {
    auto f = iMouseFrames(R"([
        {"frame": 2,   "type": "down",  "x": 120, "y": 80},
        {"frame": 4,   "type": "move",  "x": 130, "y": 90},
        {"time": 0.1,  "type": "move",  "x": 140, "y": 95},
        {"frame": 8,   "type": "up"},
        {"frame": 9,   "type": "move",  "x": 500, "y": 500},
        {"frame": 10,  "type": "click", "x": 10,  "y": 20},
        {"frame": 12,  "type": "down",  "x": 200, "y": 100}
    ])", 14);
    const std::vector<vec4> expected = {
        vec4(0),                       // 0: no click yet
        vec4(0),                       // 1
        vec4(120, 80, 120, 80),        // 2: down: click signal
        vec4(120, 80, 120, -80),       // 3: held, signal gone
        vec4(130, 90, 120, -80),       // 4: dragged
        vec4(130, 90, 120, -80),       // 5
        vec4(140, 95, 120, -80),       // 6: iTime 0.1 reached
        vec4(140, 95, 120, -80),       // 7
        vec4(140, 95, -120, -80),      // 8: released, xy kept
        vec4(140, 95, -120, -80),      // 9: move while released: ignored
        vec4(10, 20, -10, 20),         // 10: click within one frame
        vec4(10, 20, -10, -20),        // 11
        vec4(200, 100, 200, 100),      // 12: second press
        vec4(200, 100, 200, -100),     // 13
    };
    ASSERT_EQ(f.size(), expected.size());
    for (std::size_t i = 0; i < f.size(); ++i) EXPECT_EQ(f[i], expected[i]) << "frame " << i;
}

TEST(MouseScriptPlayer, UpWithPositionMovesThenReleases) {
    auto f = iMouseFrames(R"([
        {"frame": 0, "type": "down", "x": 5, "y": 6},
        {"frame": 1, "type": "up", "x": 50, "y": 60}
    ])", 3);
    EXPECT_EQ(f[1], vec4(50, 60, -5, -6));
    EXPECT_EQ(f[2], vec4(50, 60, -5, -6));
}

TEST(MouseScriptPlayer, MouseHeldAtHoldsFromFrameZeroForever) {
    MouseScriptPlayer player(mouseHeldAt(32, 48));
    MouseState mouse;
    for (int frame = 0; frame < 100; ++frame) {
        player.applyBeforeFrame(frame, frame / 60.0, mouse);
        EXPECT_EQ(mouse.uniform(), vec4(32, 48, 32, frame == 0 ? 48 : -48)) << "frame " << frame;
        mouse.endFrame();
    }
    EXPECT_TRUE(mouse.held());
    EXPECT_TRUE(player.finished());
}

TEST(MouseScriptPlayer, FrameEventsFireBeforeTimeEventsDueOnTheSameFrame) {
    // Both are due at frame 3 (iTime 0.05 at 60 fps): down (frame) fires first, then up (time),
    // so frame 3 sees a click within one frame. The other order would leave the button held.
    auto f = iMouseFrames(R"([
        {"time": 0.05, "type": "up"},
        {"frame": 3, "type": "down", "x": 1, "y": 2}
    ])", 5);
    EXPECT_EQ(f[2], vec4(0));
    EXPECT_EQ(f[3], vec4(1, 2, -1, 2));
    EXPECT_EQ(f[4], vec4(1, 2, -1, -2));
}

TEST(MouseScriptPlayer, TimeEventsDueTogetherFireInTimeOrder) {
    // At 10 fps both are due before frame 6 (iTime 0.6); listed up-first in the file, they still
    // fire down (0.51) then up (0.52).
    auto f = iMouseFrames(R"([
        {"time": 0.52, "type": "up"},
        {"time": 0.51, "type": "down", "x": 7, "y": 8}
    ])", 7, 10.0);
    EXPECT_EQ(f[5], vec4(0));
    EXPECT_EQ(f[6], vec4(7, 8, -7, 8));
}

TEST(MouseScriptPlayer, TimeEventFiresOnFirstFrameWhoseITimeReachesIt) {
    // 0.5 s at 60 fps is frame 30; 0.51 s is reached only at frame 31 (iTime 0.5166...).
    auto f = iMouseFrames(R"([
        {"time": 0.5,  "type": "down", "x": 3, "y": 4},
        {"time": 0.51, "type": "move", "x": 9, "y": 9}
    ])", 32);
    EXPECT_EQ(f[29], vec4(0));
    EXPECT_EQ(f[30], vec4(3, 4, 3, 4));
    EXPECT_EQ(f[31], vec4(9, 9, 3, -4));
}

TEST(MouseScriptPlayer, TimeWrittenAsFrameOverFpsSurvivesRounding) {
    MouseScript script;
    script.events.push_back({ScriptMoment::atTime(3.7), MouseScriptEvent::Type::Down,
                             glm::vec2(1, 1)});
    MouseScriptPlayer player(std::move(script));
    MouseState mouse;
    const double dt = 1.0 / 30.0;
    ASSERT_LT(111 * dt, 3.7);  // 3.6999999999999997: the rounding this guards against
    for (int frame = 0; frame <= 111; ++frame) {
        player.applyBeforeFrame(frame, frame * dt, mouse);
        EXPECT_EQ(mouse.held(), frame >= 111) << "frame " << frame;
        mouse.endFrame();
    }
}

}  // namespace
}  // namespace toyhost
