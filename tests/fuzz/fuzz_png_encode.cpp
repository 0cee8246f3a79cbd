// libFuzzer target: toyhost's PNG encoder (runtime/image/PngEncoder.h) on arbitrary RGBA images:
// byte 0 picks the width (1..256 pixels: runs longer than a deflate match), byte 1 the deflate
// (the fast path or a libdeflate level) and the row filter, the rest are the pixels (as many
// whole rows as there are). libpng must decode every file to exactly those pixels; anything else
// traps.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <png.h>

#include "image/PngEncoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const int width = 1 + data[0];
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    const int height = static_cast<int>((size - 2) / rowBytes);
    if (height == 0) return 0;
    static constexpr toyhost::PngFilter kFilters[] = {toyhost::PngFilter::None, toyhost::PngFilter::Sub,
                                                      toyhost::PngFilter::Up, toyhost::PngFilter::Paeth,
                                                      toyhost::PngFilter::Adaptive};
    toyhost::PngSettings settings;
    settings.filter = kFilters[data[1] % 5];
    const int deflate = data[1] / 5 % 8;  // 0..3: the fast path (the capture default); 4..7: libdeflate 0, 1, 6, 12
    static constexpr int kLevels[] = {0, 1, 6, 12};
    settings.deflate = deflate < 4 ? toyhost::PngDeflate::FastRuns : toyhost::PngDeflate::Libdeflate;
    settings.deflateLevel = deflate < 4 ? 1 : kLevels[deflate - 4];

    const std::uint8_t* pixels = data + 2;
    std::vector<const std::uint8_t*> rows(static_cast<std::size_t>(height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = pixels + y * rowBytes;
    toyhost::PngEncoder encoder;
    const std::span<const std::uint8_t> file = encoder.encode(rows.data(), width, height, settings);
    if (file.empty()) __builtin_trap();

    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) __builtin_trap();
    image.format = PNG_FORMAT_RGBA;
    if (static_cast<int>(image.width) != width || static_cast<int>(image.height) != height) __builtin_trap();
    std::vector<std::uint8_t> decoded(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, decoded.data(), 0, nullptr)) __builtin_trap();
    for (std::size_t i = 0; i < decoded.size(); ++i)
        if (decoded[i] != pixels[i]) __builtin_trap();
    return 0;
}
