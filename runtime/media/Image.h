// Image8 / ImageF32: plain CPU-side pixel buffers passed between media loading, capture and the
// renderer, and the one helper that converts between their row orders. No GL needed.
// Pixels are always 4 interleaved channels (RGBA); the row order differs by type (see below).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace toyhost {

// 8-bit RGBA, rows stored top row first (the order image files use).
struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// 32-bit float RGBA, rows stored BOTTOM row first (the order glReadPixels returns).
struct ImageF32 {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;
};

// Returns the RGBA pixels with the row order reversed (top-first <-> bottom-first).
// `rgba` must hold width * height * 4 values.
template <class T>
std::vector<T> flipRows(std::span<const T> rgba, int width, int height) {
    const std::size_t rowLength = static_cast<std::size_t>(width) * 4;
    std::vector<T> flipped(rgba.size());
    for (int y = 0; y < height; ++y) {
        const auto source =
            rgba.subspan(static_cast<std::size_t>(height - 1 - y) * rowLength, rowLength);
        std::copy(
            source.begin(), source.end(),
            flipped.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * rowLength));
    }
    return flipped;
}

}  // namespace toyhost
