// StandIns: deterministic pictures of the right size and kind for stock textures whose real file
// is not available (toyhost cannot ship Shadertoy's media). CPU only, no GL needed.
#pragma once

#include "image/Image.h"
#include "manifest/StockMedia.h"

namespace toyhost {

// A stand-in of the real texture's exact size: the same bytes on every run and machine (integer
// arithmetic only, seeded from the hash). Noise textures are uniform random bytes (grey noise: one
// byte per pixel in R=G=B, A=255; RGBA noise: four independent bytes); photos are tileable
// multi-octave value noise through a colour ramp, so they have detail at every mip level; the
// others get a pattern of the same nature (Bayer matrix, glyph grid, sprite frames, blue noise).
// Alpha is 255 wherever the real file has no alpha channel.
// Rows bottom first, like every image in memory.
Image8 makeStandIn(const StockMediaInfo& info);

}  // namespace toyhost
