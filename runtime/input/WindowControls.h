// WindowControls: the few keys window mode keeps for itself; every other key goes to the shader
// (the keyboard texture). Chosen to stay out of shaders' way: Space, letters, digits and arrows
// are the shader's. Pure logic (GLFW's key constants only); no GL needed.
#pragma once

#include <string>

namespace toyhost {

enum class Control { None, Help, Restart, Pause, Step, Fullscreen, Screenshot, Quit, Inspector };
inline constexpr int kControlCount = static_cast<int>(Control::Inspector) + 1;

// The control a key press means (GLFW key and modifier bits), or Control::None: the shader's key.
Control controlForKey(int glfwKey, int glfwMods);

// The help text F1 prints (also in docs/window.md and --help).
const char* controlsHelp();

}  // namespace toyhost
