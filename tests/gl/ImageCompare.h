// ImageCompare: error measures between two 8-bit RGBA images (PSNR, mean and max absolute error)
// and a visible diff image, for tests that compare renders. Plain CPU code, no GL needed.
// Every measure looks at R, G and B only: the Image pass forces alpha to 1.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>

#include "image/Image.h"

namespace toyhost::testing {

inline bool sameSize(const Image8& a, const Image8& b) {
    return a.width == b.width && a.height == b.height &&
           a.rgba.size() == static_cast<std::size_t>(a.width) * a.height * 4 && a.rgba.size() == b.rgba.size();
}

// Peak signal-to-noise ratio over RGB in dB, peak 255. +infinity when the images are identical,
// NaN when their sizes differ (so any `>=` threshold check fails).
inline double psnrRgb(const Image8& a, const Image8& b) {
    if (!sameSize(a, b)) return std::numeric_limits<double>::quiet_NaN();
    double sumSquares = 0.0;
    std::size_t samples = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c, ++samples) {
            const double d = double(a.rgba[i + c]) - double(b.rgba[i + c]);
            sumSquares += d * d;
        }
    if (sumSquares == 0.0) return std::numeric_limits<double>::infinity();
    const double meanSquare = sumSquares / double(samples);
    return 10.0 * std::log10(255.0 * 255.0 / meanSquare);
}

// Mean of |a - b| over every RGB sample, in 8-bit steps. NaN when the sizes differ.
inline double meanAbsError(const Image8& a, const Image8& b) {
    if (!sameSize(a, b)) return std::numeric_limits<double>::quiet_NaN();
    if (a.rgba.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
    return sum / (double(a.rgba.size() / 4) * 3.0);
}

// Largest |a - b| over every RGB sample, 0..255. -1 when the sizes differ.
inline int maxAbsError(const Image8& a, const Image8& b) {
    if (!sameSize(a, b)) return -1;
    int largest = 0;
    for (std::size_t i = 0; i < a.rgba.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])));
    return largest;
}

// The largest mean |a - b| over any `block` x `block` square (RGB, squares start every half
// block, so a defect of 1.5 blocks is always covered whole by one square and a 10x10 one covers
// at least 7x7 of an 8x8 square): a localised defect (a black 10x10 block) that whole-image PSNR
// averages away. -1 when the sizes differ.
inline double maxBlockMeanError(const Image8& a, const Image8& b, int block = 8) {
    if (!sameSize(a, b)) return -1.0;
    double largest = 0.0;
    const int stride = std::max(1, block / 2);
    for (int y0 = 0; y0 + block <= a.height; y0 += stride)
        for (int x0 = 0; x0 + block <= a.width; x0 += stride) {
            double sum = 0.0;
            for (int y = y0; y < y0 + block; ++y)
                for (int x = x0; x < x0 + block; ++x) {
                    const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
                    for (std::size_t c = 0; c < 3; ++c) sum += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
                }
            largest = std::max(largest, sum / (3.0 * block * block));
        }
    return largest;
}

// The largest |mean (b - a)| of one channel over one cell of a `cells` x `cells` grid: a
// systematic shift of a region (a changed Fresnel F0 or absorption constant) that code
// generation noise, which has no sign, does not make. In levels. -1 when the sizes differ.
inline double maxRegionBias(const Image8& a, const Image8& b, int cells = 4) {
    if (!sameSize(a, b)) return -1.0;
    double largest = 0.0;
    for (int cy = 0; cy < cells; ++cy)
        for (int cx = 0; cx < cells; ++cx) {
            const int x0 = a.width * cx / cells, x1 = a.width * (cx + 1) / cells;
            const int y0 = a.height * cy / cells, y1 = a.height * (cy + 1) / cells;
            double sum[3] = {0.0, 0.0, 0.0};
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
                    for (std::size_t c = 0; c < 3; ++c) sum[c] += int(b.rgba[i + c]) - int(a.rgba[i + c]);
                }
            const double n = double(x1 - x0) * double(y1 - y0);
            for (double s : sum) largest = std::max(largest, n > 0 ? std::abs(s) / n : 0.0);
        }
    return largest;
}

// |a - b| * gain per RGB channel (clamped to 255), alpha 255, rows top first like the inputs.
// Empty image when the sizes differ.
inline Image8 makeDiffImage(const Image8& a, const Image8& b, int gain) {
    Image8 diff;
    if (!sameSize(a, b)) return diff;
    diff.width = a.width;
    diff.height = a.height;
    diff.rgba.resize(a.rgba.size());
    for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
        for (std::size_t c = 0; c < 3; ++c)
            diff.rgba[i + c] = static_cast<std::uint8_t>(
                std::min(255, std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) * gain));
        diff.rgba[i + 3] = 255;
    }
    return diff;
}

}  // namespace toyhost::testing
