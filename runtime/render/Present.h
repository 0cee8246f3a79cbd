// Present: draws a pass's output (usually Image) into the default framebuffer of a window, or into
// any framebuffer at a given place (the library's Session::drawImage). Same size: a 1:1 copy, so
// the window shows exactly the pixels headless runs write. Different size (a canvas kept at the
// recording size while the window is resized): scaled (linear filtering); a window's is fitted with
// its aspect ratio kept, black bars around it. Needs the context current.
#pragma once

#include "render/Renderer.h"

namespace toyhost {

struct PresentRect {
    int x = 0, y = 0, width = 0, height = 0;  // where the canvas lands in the framebuffer, bottom-left origin
};

// Where a canvas of canvasW x canvasH is shown in a framebuffer of framebufferW x framebufferH.
PresentRect presentRect(int canvasW, int canvasH, int framebufferW, int framebufferH);

// Copies `output` into `framebuffer` (0: the default one) at `rect`; leaves both framebuffers
// bound.
void blitOutput(const PassOutput& output, unsigned int framebuffer, const PresentRect& rect);
// The same into a framebuffer that is not toyhost's (a caller's): GL's error, if the copy made one
// (a framebuffer that is not complete, a bad name), is returned.
Status drawOutput(const PassOutput& output, unsigned int framebuffer, const PresentRect& rect);

void presentToDefaultFramebuffer(const PassOutput& output, int framebufferW, int framebufferH);
// A dark grey default framebuffer: what a window shows before its shadertoy has a frame.
void clearDefaultFramebuffer(int framebufferW, int framebufferH);

}  // namespace toyhost
