// JpegDecode: decodes a JPEG held in memory with libjpeg-turbo, set up as Chromium's JPEG reader
// sets it up (the decoder behind the <img> the Shadertoy player uploads): the accurate integer
// IDCT (JDCT_ISLOW), fancy upsampling, block smoothing of progressive scans, grey expanded to
// R=G=B, alpha 255, Adobe (inverted) CMYK/YCCK turned into RGB as R = C*K/255. Corrupt data that
// libjpeg can decode past is decoded as the browser shows it; a file that ends before its image
// data does is refused, and so is a Huffman-coded file with fewer bits than its header declares
// 8x8 blocks (refused before anything is allocated), a file of more scans than the limit, and a
// decode that outlasts the time limit (image/DecodeLimits.h). No GL, no file I/O.
#pragma once

#include <span>
#include <string>

#include "core/Result.h"
#include "image/DecodeLimits.h"
#include "image/Image.h"

namespace toyhost {

// Decodes `bytes` (a whole JPEG file) to RGBA8, rows bottom first. `name` is the file the bytes
// came from (errors name it); a side longer than `limits.maxSide` is refused before anything is
// decoded.
Result<Image8> decodeJpeg(std::span<const unsigned char> bytes, const DecodeLimits& limits, const std::string& name);

}  // namespace toyhost
