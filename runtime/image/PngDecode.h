// PngDecode: decodes a PNG held in memory with libpng into the RGBA8 a browser uploads to WebGL for
// an <img> (UNPACK_COLORSPACE_CONVERSION aside): palettes and low bit depths expanded, grey to
// R=G=B, tRNS to alpha, a missing alpha 255, 16-bit channels cut to their high byte, no gamma,
// ICC or sRGB conversion, no premultiplication. Interlaced files are de-interlaced. A file whose
// data cannot hold the size its header declares is refused before the picture is allocated. No GL,
// no file I/O.
#pragma once

#include <span>
#include <string>

#include "core/Result.h"
#include "image/DecodeLimits.h"
#include "image/Image.h"

namespace toyhost {

// Decodes `bytes` (a whole PNG file) to RGBA8, rows bottom first. `name` is the file the bytes
// came from (errors name it); a side longer than `limits.maxSide` is refused from the header, and
// the decode stops when it takes longer than `limits.maxSeconds`.
Result<Image8> decodePng(std::span<const unsigned char> bytes, const DecodeLimits& limits, const std::string& name);

}  // namespace toyhost
