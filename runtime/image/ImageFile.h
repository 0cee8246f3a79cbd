// ImageFile: decodes PNG (libpng, image/PngDecode) and JPEG (libjpeg-turbo, image/JpegDecode) into the RGBA8
// pixels a browser hands to WebGL for an <img>. No GL needed.
#pragma once

#include <filesystem>

#include "core/Result.h"
#include "image/Image.h"

namespace toyhost {

// Decodes `path` to RGBA8, rows bottom first, as the Shadertoy player uploads images: grey
// becomes R=G=B=grey, a missing alpha becomes 255, no premultiplication, no colour-space or gamma
// conversion, 16-bit channels reduced to 8 bits. Errors name the path and the decoder's reason.
// The default DecodeLimits (image/DecodeLimits.h) apply: texture size, JPEG scans, decode time.
Result<Image8> loadImageFile(const std::filesystem::path& path);

}  // namespace toyhost
