// InputEvent: one thing the user did (mouse button, pointer move, key), as data. Window callbacks
// and input scripts both produce these; the Player applies them to the state the shader sees
// (MouseState, KeyboardState) before it renders a frame, so scripted and live input go through
// the same code. Pure logic, no GL needed.
#pragma once

#include "input/KeyboardState.h"
#include "input/MouseState.h"

namespace toyhost {

struct InputEvent {
    enum class Type { MouseDown, MouseMove, MouseUp, KeyDown, KeyUp };
    Type type = Type::MouseMove;
    float x = 0;   // pixels, origin bottom-left (mouse events)
    float y = 0;
    int key = 0;   // JavaScript keyCode (key events)

    static InputEvent mouseDown(float x, float y) { return {Type::MouseDown, x, y, 0}; }
    static InputEvent mouseMove(float x, float y) { return {Type::MouseMove, x, y, 0}; }
    static InputEvent mouseUp() { return {Type::MouseUp, 0, 0, 0}; }
    static InputEvent keyDown(int key) { return {Type::KeyDown, 0, 0, key}; }
    static InputEvent keyUp(int key) { return {Type::KeyUp, 0, 0, key}; }
};

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
