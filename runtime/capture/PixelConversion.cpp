#include "capture/PixelConversion.h"

#include <cstring>

namespace toyhost {

std::span<const std::uint8_t> rgba8BottomUp(const CapturedFrame& frame, std::vector<std::uint8_t>& scratch) {
    if (frame.format == PixelFormat::Rgba8) return frame.rgba8();
    const std::span<const float> floats = frame.rgba32f();
    scratch.resize(floats.size());
    for (std::size_t i = 0; i < floats.size(); ++i) scratch[i] = unorm8(floats[i]);
    return scratch;
}

std::span<const std::uint8_t> rowsTopFirst(std::span<const std::uint8_t> bottomUp, int width, int height,
                                           std::vector<std::uint8_t>& scratch) {
    const std::size_t stride = static_cast<std::size_t>(width) * 4;
    scratch.resize(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::memcpy(scratch.data() + static_cast<std::size_t>(y) * stride,
                    bottomUp.data() + static_cast<std::size_t>(height - 1 - y) * stride, stride);
    return scratch;
}

}  // namespace toyhost
