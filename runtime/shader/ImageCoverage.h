// ImageCoverage: whether an Image pass may leave canvas pixels as the previous frame left them.
// The site's canvas keeps its content between frames (preserveDrawingBuffer), and toyhost's main()
// always writes the colour, so only `discard` can leave a pixel unwritten. No GL needed.
#pragma once

#include "manifest/ManifestDesc.h"

namespace toyhost {

// True when the Image pass of `manifest` or its Common holds the word `discard` anywhere (a
// macro, an inactive #if branch and dead code count too: the answer errs towards drawing).
// When false, every pixel of the Image target is written at every draw, so a frame whose Image
// nobody reads can skip it without changing any later frame.
bool imageMayKeepPixels(const ManifestDesc& manifest);

}  // namespace toyhost
