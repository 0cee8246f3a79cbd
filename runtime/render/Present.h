// Present: draws a pass's output (usually Image) into the default framebuffer of a window. Same
// size: a 1:1 copy, so the window shows exactly the pixels headless runs write. Different size (a
// canvas kept at the recording size while the window is resized): scaled to fit with its aspect
// ratio kept, black bars around it. Needs the window's context current.
#pragma once

#include "render/Renderer.h"

namespace toyhost {

struct PresentRect {
    int x = 0, y = 0, width = 0, height = 0;  // where the canvas lands in the framebuffer, bottom-left origin
};

// Where a canvas of canvasW x canvasH is shown in a framebuffer of framebufferW x framebufferH.
PresentRect presentRect(int canvasW, int canvasH, int framebufferW, int framebufferH);

void presentToDefaultFramebuffer(const PassOutput& output, int framebufferW, int framebufferH);
// A dark grey default framebuffer: what a window shows before its shadertoy has a frame.
void clearDefaultFramebuffer(int framebufferW, int framebufferH);

}  // namespace toyhost
