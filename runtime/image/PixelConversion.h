// PixelConversion: float RGBA to the 8 bits a UNORM8 render target or an image file holds, the
// same arithmetic everywhere (readback of a float Image target, PNG of a buffer, raw stream).
// CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace toyhost {

// One float channel as a UNORM8 render target stores it: clamped to [0, 1], times 255, rounded;
// NaN gives 0.
inline std::uint8_t unorm8(float value) {
    const float v = !(value > 0.0f) ? 0.0f : (value > 1.0f ? 1.0f : value);
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

// Every value through unorm8, into `out` (resized to fit; no allocation once it is large enough).
void toUnorm8(std::span<const float> values, std::vector<std::uint8_t>& out);

}  // namespace toyhost
