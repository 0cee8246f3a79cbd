#include "input/MouseState.h"

namespace toyhost {

void MouseState::press(float x, float y) {
    position_ = {x, y};
    clickOrigin_ = {x, y};
    held_ = true;
    clickedThisFrame_ = true;
    everClicked_ = true;
}

void MouseState::move(float x, float y) {
    if (held_) position_ = {x, y};
}

void MouseState::release() { held_ = false; }

glm::vec4 MouseState::uniform() const {
    if (!everClicked_) return glm::vec4(0.0f);
    return {position_.x, position_.y,
            held_ ? clickOrigin_.x : -clickOrigin_.x,
            clickedThisFrame_ ? clickOrigin_.y : -clickOrigin_.y};
}

void MouseState::endFrame() { clickedThisFrame_ = false; }

}  // namespace toyhost
