// PixelConversion: float RGBA to the 8 bits a UNORM8 render target or an image file holds, the
// same arithmetic everywhere (readback of a float Image target, PNG of a buffer, raw stream), and
// rows read back from GL (bottom first) into a caller's memory in either row order and type.
// CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>
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

// `height` rows of `width` RGBA values, bottom row first (as GL reads them), into `out` (exactly
// width * height * 4 values) with the top row first when `topFirst`, in one pass: the same type
// copied; floats to 8 bits as unorm8 (a float target as an 8-bit one reads); 8 bits to floats as
// level / 255 (an 8-bit target as floats).
template <class Source, class T>
void convertRgbaRows(const Source* rows, std::span<T> out, int width, int height, bool topFirst) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height; ++y) {
        const Source* from = rows + static_cast<std::size_t>(topFirst ? height - 1 - y : y) * row;
        T* to = out.data() + static_cast<std::size_t>(y) * row;
        if constexpr (std::is_same_v<Source, T>) std::memcpy(to, from, row * sizeof(T));
        else if constexpr (std::is_same_v<T, float>)
            for (std::size_t i = 0; i < row; ++i) to[i] = from[i] / 255.0f;
        else
            for (std::size_t i = 0; i < row; ++i) to[i] = unorm8(from[i]);
    }
}

}  // namespace toyhost
