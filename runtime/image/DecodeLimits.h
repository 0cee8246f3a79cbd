// DecodeLimits: what the image decoders (PngDecode, JpegDecode) refuse: a side over the largest
// texture toyhost makes (from the header, before decoding), a JPEG of too many scans, a decode that
// takes too long. No GL needed.
#pragma once

#include <string>

#include "core/Defaults.h"
#include "core/Result.h"

namespace toyhost {

struct DecodeLimits {
    int maxSide = defaults::kMaxCanvasSide;
    int maxScans = defaults::kMaxJpegScans;            // progressive JPEG scans
    double maxSeconds = defaults::kImageDecodeSeconds;  // CPU time of the decoding thread for one image
};

// "30 s" (whole seconds when whole, else one decimal).
inline std::string secondsText(double seconds) {
    const long whole = static_cast<long>(seconds);
    if (static_cast<double>(whole) == seconds) return std::to_string(whole) + " s";
    std::string text = std::to_string(seconds);
    return text.substr(0, text.find('.') + 2) + " s";
}

// The error for a decode stopped after `limits.maxSeconds`, naming `file`.
inline Error decodeTooSlow(const std::string& file, const DecodeLimits& limits, const std::string& where) {
    return fileError(file,
                     "cannot decode image: decoding it takes longer than the " + secondsText(limits.maxSeconds) + " of CPU time" +
                         " one image may take (stopped " + where + ")",
                     Code::ImageDecode);
}

// The error for an image of width x height whose side exceeds `maxSide`, naming `file`.
inline Error imageTooLarge(const std::string& file, int width, int height, int maxSide) {
    return fileError(file,
                     "the image is " + std::to_string(width) + "x" + std::to_string(height) + ", larger than the " +
                         std::to_string(maxSide) + " a side textures may have",
                     Code::ImageTooLarge);
}

}  // namespace toyhost
