// WindowInput: what a window's raw input means to a shader, as the site computes it. GLFW reports
// the cursor in window coordinates (top-left origin, possibly scaled on HiDPI screens) and keys as
// GLFW key numbers; the shader sees iMouse in framebuffer pixels with a bottom-left origin and the
// keyboard texture indexed by JavaScript keyCode. Pure arithmetic and a table (GLFW's header is
// used for its key constants only; nothing of GLFW is linked). No GL needed.
#pragma once

#include <glm/vec2.hpp>

namespace toyhost {

// The site's iMouse position for a cursor at (cursorX, cursorY) in a window of windowW x windowH
// whose framebuffer (the canvas) is canvasW x canvasH:
//   x = floor(cursorX / windowW * canvasW),  y = floor(canvasH - cursorY / windowH * canvasH).
glm::vec2 siteMousePosition(double cursorX, double cursorY, int windowW, int windowH, int canvasW, int canvasH);

// The JavaScript keyCode a browser reports for a GLFW key (Chrome's values where browsers differ:
// ';' 186, '=' 187, '-' 189); 0 for keys a browser does not report.
int javascriptKeyCode(int glfwKey);

}  // namespace toyhost
