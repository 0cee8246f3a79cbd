// Replays a MouseScript and a KeyScript frame by frame as InputEvents (input/InputEvent.h), which
// the Player applies before rendering the frame. Pure logic, no GL context needed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "input/InputEvent.h"
#include "input/InputScript.h"
#include "input/KeyboardState.h"
#include "input/MouseState.h"

namespace toyhost {

// Keeps the position in a sorted script: its "frame" events and its "time" events are two
// sorted runs, each consumed from the front as frames advance.
class ScriptCursor {
public:
    // `moments` of the events in script order (sorted by firesEarlier).
    explicit ScriptCursor(std::vector<ScriptMoment> moments);

    // Calls `fired(index)` for each not yet fired event that is due before rendering `frame` (at
    // `iTime`), in script order, and marks it fired. Allocates nothing.
    template <class Fired>
    void takeDue(std::int64_t frame, double iTime, Fired&& fired) {
        while (nextFrame_ < timeBegin_ && moments_[nextFrame_].dueBefore(frame, iTime)) fired(nextFrame_++);
        while (nextTime_ < moments_.size() && moments_[nextTime_].dueBefore(frame, iTime)) fired(nextTime_++);
    }
    bool finished() const { return nextFrame_ == timeBegin_ && nextTime_ == moments_.size(); }

private:
    std::vector<ScriptMoment> moments_;
    std::size_t timeBegin_ = 0;  // first "time" event
    std::size_t nextFrame_ = 0;  // next unfired "frame" event
    std::size_t nextTime_ = 0;   // next unfired "time" event
};

// The script is sorted (stably, by firesEarlier) on construction, so hand-built scripts work too.
// Call eventsBeforeFrame(n, iTime) once per frame, with increasing n, before rendering frame n:
// it appends the events due to `out`. "click" presses and releases before the same frame.
// applyBeforeFrame does the same straight into a MouseState. A gliding "move" adds one move per
// frame, before that frame's own events, until it arrives (so a glide that arrives on the frame
// another starts, or an "up" fires, hands over at its end point).
class MouseScriptPlayer {
public:
    explicit MouseScriptPlayer(MouseScript script);
    void eventsBeforeFrame(std::int64_t frame, double iTime, std::vector<InputEvent>& out);
    void applyBeforeFrame(std::int64_t frame, double iTime, MouseState& mouse);
    bool finished() const;  // every event fired and every glide arrived

private:
    struct ActiveGlide {
        ScriptMoment start;
        MouseGlide end;
        glm::vec2 from{0.0f};
    };
    void pointerAt(glm::vec2 position) { pointer_ = position; }

    MouseScript script_;
    ScriptCursor cursor_;
    std::vector<ActiveGlide> glides_;  // reserved for every glide: no allocation per frame
    glm::vec2 pointer_{0.0f};          // where the script last put the pointer
    std::vector<InputEvent> scratch_;
};

// Same contract for keys. A "tap" presses before its frame and leaves a release pending, which
// is applied before the next frame's own events, so exactly one frame sees the key held.
class KeyScriptPlayer {
public:
    explicit KeyScriptPlayer(KeyScript script);
    void eventsBeforeFrame(std::int64_t frame, double iTime, std::vector<InputEvent>& out);
    void applyBeforeFrame(std::int64_t frame, double iTime, KeyboardState& keyboard);
    bool finished() const;  // every event fired and no tap release pending

private:
    KeyScript script_;
    ScriptCursor cursor_;
    std::vector<int> pendingReleases_;
    std::vector<InputEvent> scratch_;
};

}  // namespace toyhost
