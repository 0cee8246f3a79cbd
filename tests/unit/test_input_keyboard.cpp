// Keyboard texture rows (SEMANTICS.md "Keyboard input"), the upload revision, key names, and key
// scripts replayed frame by frame.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "input/KeyCodes.h"
#include "input/KeyboardState.h"

namespace toyhost {
namespace {

constexpr int kA = 65;
constexpr int kSpace = 32;

struct Rows {
    int held, wentDown, toggle;
    bool operator==(const Rows&) const = default;
};
std::ostream& operator<<(std::ostream& os, const Rows& r) {
    return os << "{held " << r.held << ", wentDown " << r.wentDown << ", toggle " << r.toggle
              << "}";
}

Rows rowsOf(const KeyboardState& k, int code) {
    return {k.texel(code, KeyboardState::kHeldRow), k.texel(code, KeyboardState::kWentDownRow),
            k.texel(code, KeyboardState::kToggleRow)};
}

TEST(KeyboardState, StartsAllZero) {
    KeyboardState k;
    ASSERT_EQ(k.texels().size(), 256u * 3u);
    for (auto byte : k.texels()) EXPECT_EQ(byte, 0);
    EXPECT_EQ(k.revision(), 0u);
}

TEST(KeyboardState, PressSetsAllThreeRowsAtKeyCodeColumn) {
    KeyboardState k;
    k.press(kA);
    auto t = k.texels();
    EXPECT_EQ(t[0 * 256 + kA], 255);  // row 0 (y=0) first in memory
    EXPECT_EQ(t[1 * 256 + kA], 255);
    EXPECT_EQ(t[2 * 256 + kA], 255);
    int nonZero = 0;
    for (auto byte : t) nonZero += byte != 0;
    EXPECT_EQ(nonZero, 3);
}

TEST(KeyboardState, RowsAcrossFrames) {
    KeyboardState k;
    k.press(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 255, 255}));  // frame of the press
    k.endFrame();
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 0, 255}));  // still held, went-down only one frame
    k.endFrame();
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 0, 255}));
    k.release(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{0, 0, 255}));  // toggle survives the release
    k.endFrame();
    k.press(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 255, 0}));  // second press flips the toggle back
    k.endFrame();
    k.release(kA);
    k.press(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 255, 255}));  // third press
}

TEST(KeyboardState, AutoRepeatWhileHeldChangesNothing) {
    KeyboardState k;
    k.press(kA);
    k.endFrame();
    auto revision = k.revision();
    k.press(kA);  // browser keydown repeat
    k.press(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{255, 0, 255}));
    EXPECT_EQ(k.revision(), revision);
}

TEST(KeyboardState, ReleaseInTheFrameOfThePressClearsWentDown) {
    // The site's SetKeyUp zeroes row 1 too, so such a press is visible only in the toggle row.
    KeyboardState k;
    k.press(kA);
    k.release(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{0, 0, 255}));
}

TEST(KeyboardState, KeysAreIndependent) {
    KeyboardState k;
    k.press(kA);
    k.press(kSpace);
    k.release(kA);
    EXPECT_EQ(rowsOf(k, kA), (Rows{0, 0, 255}));
    EXPECT_EQ(rowsOf(k, kSpace), (Rows{255, 255, 255}));
}

TEST(KeyboardState, RevisionChangesExactlyWhenTexelsChange) {
    KeyboardState k;
    k.endFrame();
    k.release(kA);  // not held
    EXPECT_EQ(k.revision(), 0u);
    k.press(kA);
    auto afterPress = k.revision();
    EXPECT_GT(afterPress, 0u);
    k.endFrame();  // clears row 1
    auto afterFirstFrame = k.revision();
    EXPECT_GT(afterFirstFrame, afterPress);
    for (int i = 0; i < 10; ++i) k.endFrame();  // idle frames: nothing to upload
    EXPECT_EQ(k.revision(), afterFirstFrame);
    k.release(kA);
    EXPECT_GT(k.revision(), afterFirstFrame);
}

TEST(KeyboardState, OutOfRangeKeyCodesAreIgnored) {
    KeyboardState k;
    k.press(-1);
    k.press(256);
    k.release(1000);
    EXPECT_EQ(k.revision(), 0u);
    EXPECT_EQ(k.texel(256, KeyboardState::kHeldRow), 0);
    for (auto byte : k.texels()) EXPECT_EQ(byte, 0);
}

TEST(KeyboardKeyNames, NamesMapToJavaScriptKeyCodes) {
    const std::vector<std::pair<std::string, int>> cases = {
        {"A", 65},      {"a", 65},       {"Z", 90},      {"0", 48},     {"9", 57},
        {"space", 32},  {"SPACE", 32},   {"enter", 13},  {"return", 13}, {"escape", 27},
        {"esc", 27},    {"tab", 9},      {"shift", 16},  {"ctrl", 17},  {"alt", 18},
        {"left", 37},   {"up", 38},      {"right", 39},  {"down", 40},  {"ArrowLeft", 37},
        {"f1", 112},    {"F12", 123},    {"numpad0", 96}, {"numpad9", 105}, {"backspace", 8},
        {"delete", 46}, {"65", 65},      {"255", 255},   {"10", 10},    {"comma", 188},
    };
    for (const auto& [name, code] : cases) {
        auto result = keyCodeFromName(name);
        ASSERT_TRUE(result.ok()) << name << ": " << result.error().text();
        EXPECT_EQ(*result, code) << name;
    }
}

TEST(KeyboardKeyNames, UnknownNamesAndBadNumbersAreErrors) {
    EXPECT_EQ(keyCodeFromName("spacebar").error().first().message, "unknown key \"spacebar\"");
    EXPECT_EQ(keyCodeFromName("f13").error().first().message, "unknown key \"f13\"");
    EXPECT_EQ(keyCodeFromName("").error().first().message, "unknown key \"\"");
    EXPECT_EQ(keyCodeFromName("300").error().first().message, "key code 300 is out of range 0..255");
    EXPECT_FALSE(keyCodeFromName("99999999999999999999999").ok());
}

// Runs a key script for `frames` frames at 60 fps and returns the rows of `code` per frame.
std::vector<Rows> keyFrames(const std::string& json, int code, int frames) {
    auto script = parseKeyScript(json, "keys.json");
    EXPECT_TRUE(script.ok()) << script.error().text();
    KeyScriptPlayer player(std::move(*script));
    KeyboardState keyboard;
    std::vector<Rows> out;
    for (int f = 0; f < frames; ++f) {
        player.applyBeforeFrame(f, f / 60.0, keyboard);
        out.push_back(rowsOf(keyboard, code));
        keyboard.endFrame();
    }
    return out;
}

TEST(KeyboardScriptPlayer, DownAndUpAcrossFrames) {
    auto f = keyFrames(R"([
        {"frame": 1, "type": "down", "key": "space"},
        {"frame": 4, "type": "up",   "key": 32}
    ])", kSpace, 6);
    const std::vector<Rows> expected = {
        {0, 0, 0}, {255, 255, 255}, {255, 0, 255}, {255, 0, 255}, {0, 0, 255}, {0, 0, 255}};
    EXPECT_EQ(f, expected);
}

TEST(KeyboardScriptPlayer, TapHoldsForExactlyOneFrameAndTogglesPerPress) {
    auto f = keyFrames(R"([
        {"frame": 1, "type": "tap", "key": "A"},
        {"frame": 3, "type": "tap", "key": "a"},
        {"frame": 5, "type": "tap", "key": "65"}
    ])", kA, 7);
    const std::vector<Rows> expected = {{0, 0, 0},       {255, 255, 255}, {0, 0, 255},
                                        {255, 255, 0},   {0, 0, 0},       {255, 255, 255},
                                        {0, 0, 255}};
    EXPECT_EQ(f, expected);
}

TEST(KeyboardScriptPlayer, TapReleaseHappensBeforeTheNextFramesOwnEvents) {
    // Tap on frame 1, press again on frame 2: the pending release comes first, so frame 2 sees a
    // fresh press (went-down set, toggle flipped twice).
    auto f = keyFrames(R"([
        {"frame": 1, "type": "tap",  "key": "space"},
        {"frame": 2, "type": "down", "key": "space"}
    ])", kSpace, 4);
    EXPECT_EQ(f[1], (Rows{255, 255, 255}));
    EXPECT_EQ(f[2], (Rows{255, 255, 0}));
    EXPECT_EQ(f[3], (Rows{255, 0, 0}));
}

TEST(KeyboardScriptPlayer, FinishedOnlyAfterThePendingTapRelease) {
    auto script = parseKeyScript(R"([{"frame": 0, "type": "tap", "key": "up"}])", "keys.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    KeyScriptPlayer player(std::move(*script));
    KeyboardState keyboard;
    EXPECT_FALSE(player.finished());
    player.applyBeforeFrame(0, 0.0, keyboard);
    EXPECT_FALSE(player.finished());
    keyboard.endFrame();
    player.applyBeforeFrame(1, 1 / 60.0, keyboard);
    EXPECT_TRUE(player.finished());
    EXPECT_EQ(keyboard.texel(38, KeyboardState::kHeldRow), 0);
}

}  // namespace
}  // namespace toyhost
