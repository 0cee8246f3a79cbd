// FrameBytes: turns a captured frame into the 8-bit bytes that image files and streams take
// (floats through image/PixelConversion.h's unorm8), with rows reordered top first for streams.
// CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "capture/CapturedFrame.h"

namespace toyhost {

// The frame as RGBA8, rows bottom first. An RGBA8 frame is returned as it is; an RGBA32F one is
// converted into `scratch` (each value clamped to [0, 1], times 255, rounded; NaN gives 0).
std::span<const std::uint8_t> rgba8BottomUp(const CapturedFrame& frame, std::vector<std::uint8_t>& scratch);

// `bottomUp` (width * height * 4 bytes) with its rows reversed, written into `scratch`.
std::span<const std::uint8_t> rowsTopFirst(std::span<const std::uint8_t> bottomUp, int width, int height,
                                           std::vector<std::uint8_t>& scratch);

}  // namespace toyhost
