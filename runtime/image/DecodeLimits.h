// DecodeLimits: what the image decoders (PngDecode, JpegDecode) refuse from a file's header,
// before decoding: a side over the largest texture toyhost makes.
#pragma once

#include <string>

#include "core/Result.h"

namespace toyhost {

// The error for an image of width x height whose side exceeds `maxSide`, naming `file`.
inline Error imageTooLarge(const std::string& file, int width, int height, int maxSide) {
    return fileError(file,
                     "the image is " + std::to_string(width) + "x" + std::to_string(height) + ", larger than the " +
                         std::to_string(maxSide) + " a side textures may have",
                     Code::ImageTooLarge);
}

}  // namespace toyhost
