// CapturedFrame: one read-back frame on its way from the GL thread to an encoder, and the two
// pixel layouts a capture can have. Plain data; no GL needed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace toyhost {

// What glReadPixels returned: RGBA8 from the Image target, RGBA32F from buffers (and from the
// Image target when it renders in float for EXR capture).
enum class PixelFormat { Rgba8, Rgba32f };

inline std::size_t bytesPerPixel(PixelFormat format) { return format == PixelFormat::Rgba8 ? 4 : 16; }

inline std::size_t frameBytes(int width, int height, PixelFormat format) {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * bytesPerPixel(format);
}

struct CapturedFrame {
    int frame = 0;                 // iFrame of the captured frame
    int width = 0;
    int height = 0;
    PixelFormat format = PixelFormat::Rgba8;
    std::vector<std::byte> pixels;  // rows bottom first, as glReadPixels returns them

    std::span<const std::uint8_t> rgba8() const {
        return {reinterpret_cast<const std::uint8_t*>(pixels.data()), pixels.size()};
    }
    // The buffer comes from operator new, so it is aligned for float.
    std::span<const float> rgba32f() const {
        return {reinterpret_cast<const float*>(pixels.data()), pixels.size() / sizeof(float)};
    }
};

}  // namespace toyhost
