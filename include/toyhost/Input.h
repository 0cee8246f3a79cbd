// toyhost/Input.h (public API, stable): one thing the user did (mouse button, pointer move, key) as
// data. A window's callbacks, input scripts and programs that embed toyhost all produce these; the
// session applies them, in order, to the state the shader sees (iMouse and the keyboard texture)
// before it renders the next frame. No GL needed.
#pragma once

namespace toyhost {

struct InputEvent {
    enum class Type { MouseDown, MouseMove, MouseUp, KeyDown, KeyUp };
    Type type = Type::MouseMove;
    float x = 0;  // canvas pixels, origin bottom-left, as iMouse holds them (mouse events)
    float y = 0;
    int key = 0;  // JavaScript keyCode, as the site's keyboard texture is indexed (A = 65, Space = 32)

    static InputEvent mouseDown(float x, float y) { return {Type::MouseDown, x, y, 0}; }
    static InputEvent mouseMove(float x, float y) { return {Type::MouseMove, x, y, 0}; }
    static InputEvent mouseUp() { return {Type::MouseUp, 0, 0, 0}; }
    static InputEvent keyDown(int key) { return {Type::KeyDown, 0, 0, key}; }
    static InputEvent keyUp(int key) { return {Type::KeyUp, 0, 0, key}; }
};

}  // namespace toyhost
