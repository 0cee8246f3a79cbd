// ScreenGrab: what the X server shows in a window (XGetImage on $DISPLAY), the way a person sees
// it, overlay included; F12 screenshots and captured frames are the canvas only. Rows bottom first,
// as readPng gives them (image/Image.h), alpha 255. No GL.
#pragma once

#include <string>

#include "image/Image.h"

namespace toyhost::testing {

// The window's content (`window`: an X window id as xdotool prints it); empty when it cannot be read.
Image8 grabWindow(const std::string& window);

}  // namespace toyhost::testing
