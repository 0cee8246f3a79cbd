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

MouseScriptPlayer::MouseScriptPlayer(MouseScript script)
    : script_(std::move(script)), cursor_(sortedMoments(script_.events)) {
    glides_.reserve(static_cast<std::size_t>(
        std::ranges::count_if(script_.events, [](const MouseScriptEvent& e) { return e.to.has_value(); })));
}

void MouseScriptPlayer::eventsBeforeFrame(std::int64_t frame, double iTime, std::vector<InputEvent>& out) {
    // Glides already under way move first, by the fraction of the way on their own clock (so a
    // glide that fires late, in a run that starts later, is where it would have been); a glide
    // that arrives now leaves the pointer at its end before this frame's events, so a glide that
    // starts here, or an "up", starts from there.
    // One step of `glide` for this frame; true when it has arrived.
    auto stepGlide = [&](const ActiveGlide& glide) {
        const bool byFrame = glide.start.clock == ScriptMoment::Clock::Frame;
        const double done = byFrame ? double(frame - glide.start.frame) / double(glide.end.end.frame - glide.start.frame)
                                    : (iTime - glide.start.seconds) / (glide.end.end.seconds - glide.start.seconds);
        const bool arrived = glide.end.end.dueBefore(frame, iTime);
        const float t = arrived ? 1.0f : static_cast<float>(std::clamp(done, 0.0, 1.0));
        const glm::vec2 at = glide.from + (glide.end.position - glide.from) * t;
        out.push_back(InputEvent::mouseMove(at.x, at.y));
        pointerAt(at);
        return arrived;
    };
    for (auto it = glides_.begin(); it != glides_.end();) it = stepGlide(*it) ? glides_.erase(it) : it + 1;

    using Type = MouseScriptEvent::Type;
    cursor_.takeDue(frame, iTime, [&](std::size_t i) {
        const MouseScriptEvent& e = script_.events[i];
        if (e.position) pointerAt(*e.position);
        switch (e.type) {
        case Type::Down: out.push_back(InputEvent::mouseDown(e.position->x, e.position->y)); break;
        case Type::Move:
            if (e.to) {
                // From where the pointer is (its own x, y when given); its first step is now.
                const ActiveGlide glide{e.at, *e.to, pointer_};
                if (!stepGlide(glide)) glides_.push_back(glide);
            } else {
                out.push_back(InputEvent::mouseMove(e.position->x, e.position->y));
            }
            break;
        case Type::Up:
            if (e.position) out.push_back(InputEvent::mouseMove(e.position->x, e.position->y));
            out.push_back(InputEvent::mouseUp());
            break;
        case Type::Click:
            out.push_back(InputEvent::mouseDown(e.position->x, e.position->y));
            out.push_back(InputEvent::mouseUp());
            break;
        }
    });
}

void MouseScriptPlayer::applyBeforeFrame(std::int64_t frame, double iTime, MouseState& mouse) {
    scratch_.clear();
    eventsBeforeFrame(frame, iTime, scratch_);
    KeyboardState unused;
    for (const InputEvent& e : scratch_) applyInput(e, mouse, unused);
}

bool MouseScriptPlayer::finished() const { return cursor_.finished() && glides_.empty(); }

KeyScriptPlayer::KeyScriptPlayer(KeyScript script)
    : script_(std::move(script)), cursor_(sortedMoments(script_.events)) {}

void KeyScriptPlayer::eventsBeforeFrame(std::int64_t frame, double iTime, std::vector<InputEvent>& out) {
    for (int keyCode : pendingReleases_) out.push_back(InputEvent::keyUp(keyCode));
    pendingReleases_.clear();

    using Type = KeyScriptEvent::Type;
    cursor_.takeDue(frame, iTime, [&](std::size_t i) {
        const KeyScriptEvent& e = script_.events[i];
        switch (e.type) {
        case Type::Down: out.push_back(InputEvent::keyDown(e.keyCode)); break;
        case Type::Up: out.push_back(InputEvent::keyUp(e.keyCode)); break;
        case Type::Tap:
            out.push_back(InputEvent::keyDown(e.keyCode));
            pendingReleases_.push_back(e.keyCode);
            break;
        }
    });
}

void KeyScriptPlayer::applyBeforeFrame(std::int64_t frame, double iTime, KeyboardState& keyboard) {
    scratch_.clear();
    eventsBeforeFrame(frame, iTime, scratch_);
    MouseState unused;
    for (const InputEvent& e : scratch_) applyInput(e, unused, keyboard);
}

bool KeyScriptPlayer::finished() const {
    return cursor_.finished() && pendingReleases_.empty();
}

}  // namespace toyhost

namespace toyhost {
bool operator==(const InputEvent& a, const InputEvent& b) {
    return a.type == b.type && a.x == b.x && a.y == b.y && a.key == b.key;
}
}  // namespace toyhost
