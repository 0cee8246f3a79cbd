// Input scripts: mouse and key events read from JSON files, replayed in headless runs by the
// players in InputScriptPlayer.h. This module owns the file format and its validation.
// Pure logic, no GL context needed.
//
// ---- Format ---------------------------------------------------------------------------------
// A script file is a JSON array of event objects. Every event has exactly one of
//   "frame": integer >= 0   fires before the first rendered frame whose iFrame >= this value
//   "time":  number >= 0    fires before the first rendered frame whose iTime >= this value
//                           (seconds; up to 1 microsecond early, so time = frame/fps lands
//                           on that frame despite rounding)
// and a "type". An optional "comment" string is ignored; any other field is an error.
//
// Mouse script (pixel coordinates, origin bottom-left, as iMouse holds them):
//   [ {"frame": 10, "type": "down",  "x": 120, "y": 80},    button goes down at (x, y)
//     {"time": 0.5, "type": "move",  "x": 130, "y": 90},    pointer moves (seen only while held)
//     {"frame": 40, "type": "up"},                          button goes up
//     {"frame": 41, "type": "up",    "x": 140, "y": 95},    move to (x, y), then up
//     {"frame": 60, "type": "click", "x": 10,  "y": 20} ]   down and up before the same frame:
//                                                           that frame sees w > 0 and z < 0,
//                                                           like a click shorter than a frame
//     {"frame": 70, "type": "move", "to": {"frame": 100, "x": 300, "y": 40}}
//                                                           glides in a straight line from where
//                                                           the pointer is (or from "x", "y" when
//                                                           given) to "to"'s x, y, one move per
//                                                           frame, arriving on frame 100; "to"
//                                                           takes the event's clock ("frame" or
//                                                           "time") and a later moment
//   "down", "move", "click" need "x" and "y" (a "move" with "to" may leave both out); for "up"
//   they are optional (both or neither). A drag is two lines: a "down", then a "move" with "to".
//
// Key script (key by name, case-insensitive, e.g. "A", "7", "space", "left", "f5", or by
// JavaScript keyCode as a number, e.g. 65; names are listed in KeyCodes.h):
//   [ {"frame": 3,   "type": "down", "key": "space"},       key goes down (held from now on)
//     {"frame": 9,   "type": "up",   "key": "space"},       key goes up
//     {"time": 1.25, "type": "tap",  "key": 37} ]           down before this frame, up before
//                                                           the next one: one frame held with
//                                                           the went-down row set
//
// Events may be listed in any order. They are sorted stably: all "frame" events by frame, then
// all "time" events by time; events with equal moments keep their file order. Events that
// become due on the same frame fire in that sorted order ("frame" events before "time" events,
// since the two clocks cannot be compared until the run), then that frame is rendered.
//
// Errors name the source, the event index (0-based, in file order) and the field:
//   mouse.json: event 3: "x" is missing
//   keys.json: event 0: unknown key "spacebar"
// ---------------------------------------------------------------------------------------------
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"

namespace toyhost {

// When an event fires: before frame `frame`, or before the first frame with iTime >= `seconds`.
struct ScriptMoment {
    enum class Clock { Frame, Time };
    Clock clock = Clock::Frame;
    std::int64_t frame = 0;  // Clock::Frame
    double seconds = 0.0;    // Clock::Time

    static ScriptMoment atFrame(std::int64_t frame) { return {Clock::Frame, frame, 0.0}; }
    static ScriptMoment atTime(double seconds) { return {Clock::Time, 0, seconds}; }

    // True when the event is due before rendering frame `frameNumber`, whose iTime is `iTime`.
    bool dueBefore(std::int64_t frameNumber, double iTime) const;
};

// The script order: "frame" events (by frame) before "time" events (by time).
bool firesEarlier(const ScriptMoment& a, const ScriptMoment& b);

// The end of a "move" that glides: where the pointer arrives, and when.
struct MouseGlide {
    ScriptMoment end;  // same clock as the event, later than it
    glm::vec2 position{0.0f};
};

struct MouseScriptEvent {
    enum class Type { Down, Move, Up, Click };
    ScriptMoment at;
    Type type = Type::Down;
    // Always set for Down/Click and for a Move without "to"; optional for Up and a gliding Move
    // (which then starts from wherever the pointer is).
    std::optional<glm::vec2> position;
    std::optional<MouseGlide> to;  // Move only: glide linearly to here
};

struct MouseScript {
    std::vector<MouseScriptEvent> events;  // sorted by firesEarlier, stable
};

struct KeyScriptEvent {
    enum class Type { Down, Up, Tap };
    ScriptMoment at;
    Type type = Type::Down;
    int keyCode = 0;  // 0..255
};

struct KeyScript {
    std::vector<KeyScriptEvent> events;  // sorted by firesEarlier, stable
};

// `sourceName` (usually the file path) prefixes every error message.
Result<MouseScript> parseMouseScript(std::string_view jsonText, std::string_view sourceName);
Result<KeyScript> parseKeyScript(std::string_view jsonText, std::string_view sourceName);

// The script behind the CLI option `--mouse X,Y`: the button goes down at pixel (x, y) before
// frame 0 and stays held for the whole run.
MouseScript mouseHeldAt(float x, float y);

}  // namespace toyhost
