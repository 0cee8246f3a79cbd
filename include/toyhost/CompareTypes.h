// toyhost/CompareTypes.h (public API, stable): the vocabulary of comparing frames: when two frames
// count as equal (CompareTolerance), what one compared frame measures (FrameDifference), and
// compareImages, the plain arithmetic over two RGBA8 images that toyhost compare and
// compareShadertoys (toyhost/Compare.h) use. No GL needed.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <toyhost/Export.h>
#include <toyhost/Result.h>

namespace toyhost {

// When two frames count as equal. Neither set: only identical frames are equal. Both set: both
// must hold.
struct CompareTolerance {
    std::optional<double> minPsnr;  // equal when PSNR >= minPsnr (dB)
    std::optional<int> maxDiff;     // equal when no sample differs by more than maxDiff levels;
                                    // a pixel counts as differing only beyond it
};

// One frame of two images compared. Samples are 8-bit levels; the Image pass is compared on R, G
// and B (its alpha is always 1), a buffer on R, G, B and A.
struct FrameDifference {
    int frame = 0;      // iFrame
    double time = 0;    // iTime
    double psnr = 0;    // dB over the compared samples, peak 255; +infinity when identical
    int maxDiff = 0;    // largest |a - b| of one sample, 0..255
    double meanDiff = 0;             // mean |a - b| over the compared samples
    std::int64_t differingPixels = 0;  // pixels with a sample differing by more than the tolerance's maxDiff (else 0)
    int firstX = -1;    // the first differing pixel, scanning rows from the top row, left to right:
    int firstY = -1;    // x from the left, y from the top (-1 when none)
    bool withinTolerance = true;
    // |a - b| * gain per R, G, B (clamped to 255), alpha 255, rows top first, width * height * 4
    // bytes; filled only when asked for (CompareSettings::keepDiffImages) and the frame is not
    // within tolerance.
    std::vector<std::uint8_t> diffImage;
};

// Compares two RGBA8 images of width * height * 4 bytes (any row order, the same for both; firstY
// counts rows in that order). `channels` is 3 (R, G, B) or 4. Writes the difference image into
// `diffImage` (resized) when given. Errors: sizes that do not match, channels other than 3 or 4.
TOYHOST_API Result<FrameDifference> compareImages(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b,
                                                  int width, int height, int channels, const CompareTolerance& tolerance = {},
                                                  std::vector<std::uint8_t>* diffImage = nullptr, int diffGain = 0);

}  // namespace toyhost
