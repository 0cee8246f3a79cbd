#include "input/InputScriptPlayer.h"

#include <algorithm>
#include <utility>

namespace toyhost {

namespace {
// Sorts the events into script order and returns their moments.
template <class Event>
std::vector<ScriptMoment> sortedMoments(std::vector<Event>& events) {
    std::ranges::stable_sort(events, firesEarlier, &Event::at);
    std::vector<ScriptMoment> moments;
    moments.reserve(events.size());
    for (const Event& e : events) moments.push_back(e.at);
    return moments;
}
}  // namespace

ScriptCursor::ScriptCursor(std::vector<ScriptMoment> moments) : moments_(std::move(moments)) {
    auto firstTime = std::ranges::find(moments_, ScriptMoment::Clock::Time, &ScriptMoment::clock);
    timeBegin_ = static_cast<std::size_t>(firstTime - moments_.begin());
    nextTime_ = timeBegin_;
}

std::vector<std::size_t> ScriptCursor::takeDue(std::int64_t frame, double iTime) {
    std::vector<std::size_t> due;
    while (nextFrame_ < timeBegin_ && moments_[nextFrame_].dueBefore(frame, iTime))
        due.push_back(nextFrame_++);
    while (nextTime_ < moments_.size() && moments_[nextTime_].dueBefore(frame, iTime))
        due.push_back(nextTime_++);
    return due;
}

MouseScriptPlayer::MouseScriptPlayer(MouseScript script)
    : script_(std::move(script)), cursor_(sortedMoments(script_.events)) {}

void MouseScriptPlayer::applyBeforeFrame(std::int64_t frame, double iTime, MouseState& mouse) {
    using Type = MouseScriptEvent::Type;
    for (std::size_t i : cursor_.takeDue(frame, iTime)) {
        const MouseScriptEvent& e = script_.events[i];
        switch (e.type) {
        case Type::Down: mouse.press(e.position->x, e.position->y); break;
        case Type::Move: mouse.move(e.position->x, e.position->y); break;
        case Type::Up:
            if (e.position) mouse.move(e.position->x, e.position->y);
            mouse.release();
            break;
        case Type::Click:
            mouse.press(e.position->x, e.position->y);
            mouse.release();
            break;
        }
    }
}

bool MouseScriptPlayer::finished() const { return cursor_.finished(); }

KeyScriptPlayer::KeyScriptPlayer(KeyScript script)
    : script_(std::move(script)), cursor_(sortedMoments(script_.events)) {}

void KeyScriptPlayer::applyBeforeFrame(std::int64_t frame, double iTime,
                                       KeyboardState& keyboard) {
    for (int keyCode : std::exchange(pendingReleases_, {})) keyboard.release(keyCode);

    using Type = KeyScriptEvent::Type;
    for (std::size_t i : cursor_.takeDue(frame, iTime)) {
        const KeyScriptEvent& e = script_.events[i];
        switch (e.type) {
        case Type::Down: keyboard.press(e.keyCode); break;
        case Type::Up: keyboard.release(e.keyCode); break;
        case Type::Tap:
            keyboard.press(e.keyCode);
            pendingReleases_.push_back(e.keyCode);
            break;
        }
    }
}

bool KeyScriptPlayer::finished() const {
    return cursor_.finished() && pendingReleases_.empty();
}

}  // namespace toyhost
