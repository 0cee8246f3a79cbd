// LibpngDecode: decodes a PNG in memory with libpng's own decoder (its simplified API), so tests
// check toyhost's PNG writers against the reference reader. CPU only; needs libpng and GoogleTest.
#pragma once

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <span>
#include <vector>

namespace toyhost::testing {

// The pixels as RGBA8 rows top first; a decoding failure is a test failure and gives {}.
inline std::vector<std::uint8_t> libpngDecode(std::span<const std::uint8_t> file, int& width, int& height) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) {
        ADD_FAILURE() << "libpng: " << image.message;
        return {};
    }
    image.format = PNG_FORMAT_RGBA;
    width = static_cast<int>(image.width);
    height = static_cast<int>(image.height);
    std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
        ADD_FAILURE() << "libpng: " << image.message;
        return {};
    }
    return pixels;
}

}  // namespace toyhost::testing
