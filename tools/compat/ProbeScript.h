// ProbeScript: what the compatibility probe does to a shader and how it judges it, as pure
// functions (unit-tested without GL): the visitor's mouse per frame and the error line a failure
// shows. No GL needed.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "toyhost/Input.h"

namespace toyhost::compat {

// The mouse on frame `frame` of `frames` at width x height: pressed on frame 1, dragged along a
// diagonal that never crosses the exact centre (a `0/0` there is the shader's, not the site's
// visitor's), released two frames before the end, so the last frames show the shader after a
// click as well as "click to reset" shaders do.
inline std::vector<InputEvent> probeMouseAt(int frame, int frames, int width, int height) {
    std::vector<InputEvent> events;
    const int release = std::max(2, frames - 2);
    auto at = [&](float t) {
        return std::pair<float, float>{width * (0.31f + 0.42f * t), height * (0.37f + 0.2f * t)};
    };
    if (frame == 1) {
        const auto [x, y] = at(0.0f);
        events.push_back(InputEvent::mouseDown(x, y));
    } else if (frame > 1 && frame < release) {
        const auto [x, y] = at(std::min(1.0f, (frame - 1) / static_cast<float>(std::max(1, release - 2))));
        events.push_back(InputEvent::mouseMove(x, y));
    } else if (frame == release) {
        events.push_back(InputEvent::mouseUp());
    }
    return events;
}

// The keys a shader that draws only while a key is held most likely waits for (the site's
// keyboard texture codes, as in JavaScript's keyCode), tried in this order, each held for
// kKeyHoldFrames frames and released before the next.
struct ProbeKey {
    int code;
    const char* name;
};
inline constexpr ProbeKey kProbeKeys[] = {{32, "Space"}, {13, "Enter"}, {37, "Left"},  {38, "Up"},
                                          {39, "Right"}, {40, "Down"},  {87, "W"},     {65, "A"},
                                          {83, "S"},     {68, "D"},     {16, "Shift"}, {17, "Control"}};
inline constexpr int kProbeKeyCount = static_cast<int>(sizeof(kProbeKeys) / sizeof(kProbeKeys[0]));
inline constexpr int kKeyHoldFrames = 3;
inline constexpr int probeKeyFrames() { return kProbeKeyCount * kKeyHoldFrames + 1; }

// The key held on frame `frame` of the key script (-1 after the last), and the events of that
// frame: key i goes down on frame i * kKeyHoldFrames and up on the frame the next one goes down.
inline int probeKeyHeldAt(int frame) {
    const int key = frame / kKeyHoldFrames;
    return frame >= 0 && key < kProbeKeyCount ? key : -1;
}
inline std::vector<InputEvent> probeKeysAt(int frame) {
    std::vector<InputEvent> events;
    if (frame < 0 || frame % kKeyHoldFrames != 0) return events;
    const int key = frame / kKeyHoldFrames;
    if (key > 0 && key <= kProbeKeyCount) events.push_back(InputEvent::keyUp(kProbeKeys[key - 1].code));
    if (key < kProbeKeyCount) events.push_back(InputEvent::keyDown(kProbeKeys[key].code));
    return events;
}

// The line of a failure's text to show: the first that says "error" (a driver's warnings come
// first and hide it), else the first line.
inline std::string firstErrorLine(const std::string& text) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string line = text.substr(start, end - start);
        std::string lower = line;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
        if (lower.find("error") != std::string::npos) return line;
        start = end + 1;
    }
    return text.substr(0, text.find('\n'));
}

}  // namespace toyhost::compat
