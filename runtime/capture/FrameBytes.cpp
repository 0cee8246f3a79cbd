#include "capture/FrameBytes.h"

#include "image/PixelConversion.h"

namespace toyhost {

std::span<const std::uint8_t> rgba8BottomUp(const CapturedFrame& frame, std::vector<std::uint8_t>& scratch) {
    if (frame.format == PixelFormat::Rgba8) return frame.rgba8();
    toUnorm8(frame.rgba32f(), scratch);
    return scratch;
}

std::span<const std::uint8_t> rowsTopFirst(std::span<const std::uint8_t> bottomUp, int width, int height,
                                           std::vector<std::uint8_t>& scratch) {
    copyFlipped(bottomUp, width, height, scratch);
    return scratch;
}

}  // namespace toyhost
