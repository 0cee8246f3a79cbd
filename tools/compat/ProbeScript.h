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
