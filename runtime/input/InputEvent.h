// InputEvent (the public struct, toyhost/Input.h) applied to the state the shader sees
// (MouseState, KeyboardState): window callbacks, input scripts and programs that embed toyhost go
// through the same code. Pure logic, no GL needed.
#pragma once

#include <toyhost/Input.h>

#include "input/KeyboardState.h"
#include "input/MouseState.h"

namespace toyhost {

bool operator==(const InputEvent& a, const InputEvent& b);

inline void applyInput(const InputEvent& e, MouseState& mouse, KeyboardState& keyboard) {
    switch (e.type) {
        case InputEvent::Type::MouseDown: mouse.press(e.x, e.y); break;
        case InputEvent::Type::MouseMove: mouse.move(e.x, e.y); break;
        case InputEvent::Type::MouseUp: mouse.release(); break;
        case InputEvent::Type::KeyDown: keyboard.press(e.key); break;
        case InputEvent::Type::KeyUp: keyboard.release(e.key); break;
    }
}

}  // namespace toyhost
