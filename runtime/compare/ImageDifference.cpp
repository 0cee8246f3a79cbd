// ImageDifference: toyhost::compareImages (include/toyhost/CompareTypes.h), the arithmetic of comparing
// two RGBA8 frames: PSNR, largest and mean sample difference, differing pixels, the first one, and
// the difference image. Pure, no GL (tests/unit/test_image_difference.cpp checks it on hand-made
// images).
#include <toyhost/CompareTypes.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "compare/CompareChecks.h"
#include "core/Defaults.h"

namespace toyhost {

namespace {
std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

Error settingError(const char* setting, std::string message) {
    Error error(std::move(message), Code::Usage);
    error.diagnostics.front().field = setting;
    return error;
}
}  // namespace

Status checkCompareTolerance(const CompareTolerance& tolerance, int diffGain) {
    // +infinity is a tolerance (only identical frames are equal); NaN compares false with
    // everything and would make every frame differ.
    if (tolerance.minPsnr && (std::isnan(*tolerance.minPsnr) || *tolerance.minPsnr <= 0))
        return settingError("min_psnr", "must be more than 0 dB (infinity: identical only), not " +
                                            number(*tolerance.minPsnr));
    if (tolerance.maxDiff && (*tolerance.maxDiff < 0 || *tolerance.maxDiff > 255))
        return settingError("max_diff", "must be between 0 and 255 levels, not " + std::to_string(*tolerance.maxDiff));
    if (diffGain < 0 || diffGain > 255)
        return settingError("diff_gain", "must be between 0 (toyhost's default, " +
                                             std::to_string(defaults::kCompareDiffGain) + ") and 255, not " +
                                             std::to_string(diffGain));
    return okStatus();
}

Result<FrameDifference> compareImages(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b, int width,
                                      int height, int channels, const CompareTolerance& tolerance,
                                      std::vector<std::uint8_t>* diffImage, int diffGain) {
    if (Status checked = checkCompareTolerance(tolerance, diffGain); !checked) return checked.error();
    if (channels != 3 && channels != 4)
        return Error("compareImages: channels must be 3 (RGB) or 4 (RGBA), not " + std::to_string(channels),
                     Code::Usage);
    if (width < 0 || height < 0)
        return Error("compareImages: a negative size (" + std::to_string(width) + "x" + std::to_string(height) + ")",
                     Code::Usage);
    const std::size_t values = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    if (a.size() != values || b.size() != values)
        return Error("compareImages: the images hold " + std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                         " bytes, " + std::to_string(width) + "x" + std::to_string(height) + " RGBA8 is " +
                         std::to_string(values),
                     Code::Usage);
    const int gain = diffGain > 0 ? diffGain : defaults::kCompareDiffGain;
    // A pixel differs when one of its samples differs by more than this.
    const int pixelThreshold = tolerance.maxDiff ? std::max(0, *tolerance.maxDiff) : 0;
    if (diffImage) diffImage->assign(values, 0);

    FrameDifference d;
    std::uint64_t sumAbs = 0;
    std::uint64_t sumSquares = 0;  // at most 255^2 * 4 * 16384^2 < 2^64
    for (std::size_t i = 0; i < values; i += 4) {
        int largest = 0;
        for (int c = 0; c < channels; ++c) {
            const int diff = std::abs(int(a[i + c]) - int(b[i + c]));
            sumAbs += static_cast<std::uint64_t>(diff);
            sumSquares += static_cast<std::uint64_t>(diff * diff);
            largest = std::max(largest, diff);
        }
        d.maxDiff = std::max(d.maxDiff, largest);
        if (largest > pixelThreshold) {
            if (d.differingPixels == 0) {
                const std::size_t pixel = i / 4;
                d.firstX = static_cast<int>(pixel % static_cast<std::size_t>(width));
                d.firstY = static_cast<int>(pixel / static_cast<std::size_t>(width));
            }
            ++d.differingPixels;
        }
        if (diffImage) {
            for (int c = 0; c < 3; ++c)
                (*diffImage)[i + c] = static_cast<std::uint8_t>(std::min(255, std::abs(int(a[i + c]) - int(b[i + c])) * gain));
            (*diffImage)[i + 3] = 255;
        }
    }
    const double samples = static_cast<double>(values / 4) * channels;
    d.meanDiff = samples > 0 ? static_cast<double>(sumAbs) / samples : 0.0;
    d.psnr = sumSquares == 0 ? std::numeric_limits<double>::infinity()
                             : 10.0 * std::log10(255.0 * 255.0 * samples / static_cast<double>(sumSquares));
    const bool psnrOk = !tolerance.minPsnr || d.psnr >= *tolerance.minPsnr;
    const bool diffOk = tolerance.maxDiff ? d.maxDiff <= *tolerance.maxDiff : true;
    const bool exact = tolerance.minPsnr || tolerance.maxDiff ? true : d.maxDiff == 0;
    d.withinTolerance = psnrOk && diffOk && exact;
    return d;
}

}  // namespace toyhost
