// Image8 / ImageF32: CPU-side RGBA pixels passed between decoding, stand-ins, the renderer and
// capture. Every image in memory has its rows BOTTOM row first, as GL uploads and reads them;
// files store the top row first, and flipRows() (used only by this module's readers and writers
// and by stand-in generation) is the one place that converts. No GL needed.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace toyhost {

// The two pixel layouts toyhost reads back and writes: RGBA8 (what the screen shows) and RGBA32F
// (buffers, and the Image target when its raw floats are wanted).
enum class PixelFormat { Rgba8, Rgba32f };

inline std::size_t bytesPerPixel(PixelFormat format) { return format == PixelFormat::Rgba8 ? 4 : 16; }

inline std::size_t frameBytes(int width, int height, PixelFormat format) {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * bytesPerPixel(format);
}

// 8-bit RGBA, rows bottom first.
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// 32-bit float RGBA, rows bottom first.
struct ImageF32 {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;
};

// Reverses the row order of `rgba` (width * height * 4 values) in place.
template <class T>
void flipRows(std::span<T> rgba, int width, int height) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(rgba.begin() + static_cast<std::ptrdiff_t>(y * row),
                         rgba.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                         rgba.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
}

// Writes `rgba` with its rows reversed into `out` (resized to fit); `rgba` is left unchanged.
template <class T>
void copyFlipped(std::span<const T> rgba, int width, int height, std::vector<std::remove_const_t<T>>& out) {
    const std::size_t row = static_cast<std::size_t>(width) * 4;
    out.resize(rgba.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(rgba.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row), row,
                    out.begin() + static_cast<std::ptrdiff_t>(y * row));
}

}  // namespace toyhost
