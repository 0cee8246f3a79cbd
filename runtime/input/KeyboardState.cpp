#include "input/KeyboardState.h"

#include <algorithm>

namespace toyhost {

namespace {
constexpr std::uint8_t kOn = 255;
bool inRange(int keyCode) { return keyCode >= 0 && keyCode < KeyboardState::kWidth; }
}  // namespace

void KeyboardState::press(int keyCode) {
    if (!inRange(keyCode) || at(keyCode, kHeldRow) == kOn) return;  // auto-repeat: no change
    at(keyCode, kHeldRow) = kOn;
    at(keyCode, kWentDownRow) = kOn;
    at(keyCode, kToggleRow) = kOn - at(keyCode, kToggleRow);
    ++revision_;
}

void KeyboardState::release(int keyCode) {
    if (!inRange(keyCode) || at(keyCode, kHeldRow) == 0) return;
    at(keyCode, kHeldRow) = 0;
    at(keyCode, kWentDownRow) = 0;
    ++revision_;
}

void KeyboardState::endFrame() {
    auto row = std::span(texels_).subspan(kWentDownRow * kWidth, kWidth);
    if (std::ranges::none_of(row, [](std::uint8_t v) { return v != 0; })) return;
    std::ranges::fill(row, std::uint8_t{0});
    ++revision_;
}

std::uint8_t KeyboardState::texel(int keyCode, Row row) const {
    return inRange(keyCode) ? texels_[row * kWidth + keyCode] : 0;
}

}  // namespace toyhost
