// CapturedFrame: one read-back frame on its way from the GL thread to an encoder (its pixel
// layout is image/Image.h's PixelFormat). Plain data; no GL needed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "image/Image.h"

namespace toyhost {

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
