// PixelConversion: turns a captured frame into the 8-bit bytes that image files and streams take:
// float buffers clamped and rounded as a UNORM8 render target would store them, and rows
// reordered top first for streams. CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "capture/CapturedFrame.h"

namespace toyhost {

// One float channel as a UNORM8 render target stores it: clamped to [0, 1], times 255, rounded;
// NaN gives 0.
inline std::uint8_t unorm8(float value) {
    const float v = !(value > 0.0f) ? 0.0f : (value > 1.0f ? 1.0f : value);
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

// The frame as RGBA8, rows bottom first. An RGBA8 frame is returned as it is; an RGBA32F one is
// converted into `scratch` (each value clamped to [0, 1], times 255, rounded; NaN gives 0).
std::span<const std::uint8_t> rgba8BottomUp(const CapturedFrame& frame, std::vector<std::uint8_t>& scratch);

// `bottomUp` (width * height * 4 bytes) with its rows reversed, written into `scratch`.
std::span<const std::uint8_t> rowsTopFirst(std::span<const std::uint8_t> bottomUp, int width, int height,
                                           std::vector<std::uint8_t>& scratch);

}  // namespace toyhost
