#include "input/WindowControls.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace toyhost {

Control controlForKey(int key, int mods) {
    const bool ctrl = (mods & GLFW_MOD_CONTROL) != 0;
    switch (key) {
        case GLFW_KEY_F1: return Control::Help;
        case GLFW_KEY_F2: return Control::Inspector;
        case GLFW_KEY_F5: return Control::Restart;
        case GLFW_KEY_R: return ctrl ? Control::Restart : Control::None;
        case GLFW_KEY_F6: case GLFW_KEY_PAUSE: return Control::Pause;
        case GLFW_KEY_F7: return Control::Step;
        case GLFW_KEY_F11: return Control::Fullscreen;
        case GLFW_KEY_F12: return Control::Screenshot;
        case GLFW_KEY_ESCAPE: return Control::Quit;
        case GLFW_KEY_Q: return ctrl ? Control::Quit : Control::None;
        default: return Control::None;
    }
}

const char* controlsHelp() {
    return "F1 this help | F2 inspector (buffers, values under the cursor) | F5 or Ctrl+R restart (iFrame 0, iTime 0, buffers cleared) | F6 or Pause pause/resume | "
           "F7 one frame while paused | F11 fullscreen | F12 screenshot (PNG) | Esc or Ctrl+Q quit | "
           "every other key goes to the shader";
}

}  // namespace toyhost
