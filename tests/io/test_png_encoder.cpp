// PngEncoder: every --png-level, every row filter and both deflates write a standard PNG that libpng itself
// decodes to exactly the pixels given (images with flat areas, gradients, noise and odd sizes).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <png.h>

#include "LibpngDecode.h"

#include "TestFolder.h"
#include "TestPictures.h"
#include "image/ImageWriters.h"
#include "image/PngEncoder.h"

using namespace toyhost;
using toyhost::testing::libpngDecode;

namespace {
using toyhost::testing::Picture;

// Flat panels and lines (runs), a smooth gradient (filters pay), noise (incompressible), and a
// 1x1 and a one-row image (the first-row and first-pixel cases of every filter).
std::vector<Picture> pictures() {
    std::vector<Picture> all;
    auto make = [&](std::string name, int w, int h, auto pixel) {
        all.push_back(toyhost::testing::makePicture(std::move(name), w, h, pixel));
    };
    make("flat", 97, 61, [](int x, int y, int c) { return (x / 20 + y / 15) % 2 ? 40 + c * 60 : (x % 7 == 0 ? 0 : 250); });
    make("gradient", 131, 77, [](int x, int y, int c) { return c == 3 ? 255 - y : (x * (c + 1) + y * 3) & 255; });
    std::uint32_t state = 12345;
    make("noise", 64, 48, [&](int, int, int) {
        state = state * 1664525u + 1013904223u;
        return static_cast<int>(state >> 24);
    });
    make("pixel", 1, 1, [](int, int, int c) { return 200 - c * 50; });
    make("row", 300, 1, [](int x, int, int c) { return x * (c + 2); });
    return all;
}

std::vector<const std::uint8_t*> rowTable(const Picture& p) {
    std::vector<const std::uint8_t*> rows;
    for (int y = 0; y < p.height; ++y) rows.push_back(p.rgba.data() + static_cast<std::size_t>(y) * p.width * 4);
    return rows;
}
}  // namespace

TEST(PngEncoder, EveryFilterAndDeflateRoundTripsExactlyThroughLibpng) {
    PngEncoder encoder;  // one encoder for all: switching level and filter between files
    for (const Picture& p : pictures()) {
        const std::vector<const std::uint8_t*> rows = rowTable(p);
        for (int level : {0, 1, 2, 4, 6, 9, 12})
            for (PngFilter filter : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth, PngFilter::Adaptive}) {
                const std::span<const std::uint8_t> file = encoder.encode(rows.data(), p.width, p.height, {level, filter});
                ASSERT_FALSE(file.empty());
                int w = 0, h = 0;
                const std::vector<std::uint8_t> decoded = libpngDecode(file, w, h);
                EXPECT_EQ(w, p.width);
                EXPECT_EQ(h, p.height);
                EXPECT_TRUE(decoded == p.rgba) << p.name << " deflate level " << level << " filter " << static_cast<int>(filter);
            }
        for (PngFilter filter : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth, PngFilter::Adaptive}) {
            const std::span<const std::uint8_t> file =
                encoder.encode(rows.data(), p.width, p.height, {1, filter, PngDeflate::FastRuns});
            ASSERT_FALSE(file.empty());
            int w = 0, h = 0;
            const std::vector<std::uint8_t> decoded = libpngDecode(file, w, h);
            EXPECT_EQ(w, p.width);
            EXPECT_EQ(h, p.height);
            EXPECT_TRUE(decoded == p.rgba) << p.name << " fast path, filter " << static_cast<int>(filter);
        }
    }
}

TEST(PngEncoder, EveryPngLevelWritesAFileLibpngReadsBackExactly) {
    toyhost::testing::TestFolder folder;
    ImageScratch scratch;
    for (const Picture& p : pictures()) {
        // writePng takes rows bottom first.
        std::vector<std::uint8_t> bottomUp;
        for (int y = p.height - 1; y >= 0; --y)
            bottomUp.insert(bottomUp.end(), p.rgba.begin() + static_cast<std::ptrdiff_t>(y) * p.width * 4,
                            p.rgba.begin() + static_cast<std::ptrdiff_t>(y + 1) * p.width * 4);
        for (int level = 0; level <= 9; ++level) {
            const std::filesystem::path path = folder.path / (p.name + std::to_string(level) + ".png");
            const Status written = writePng(path, p.width, p.height, bottomUp, level, &scratch);
            ASSERT_TRUE(written.ok()) << written.error().text();
            png_image image{};
            image.version = PNG_IMAGE_VERSION;
            ASSERT_TRUE(png_image_begin_read_from_file(&image, path.c_str())) << image.message;
            image.format = PNG_FORMAT_RGBA;
            std::vector<std::uint8_t> decoded(PNG_IMAGE_SIZE(image));
            ASSERT_TRUE(png_image_finish_read(&image, nullptr, decoded.data(), 0, nullptr)) << image.message;
            EXPECT_TRUE(decoded == p.rgba) << p.name << " --png-level " << level;
        }
    }
}

TEST(PngEncoder, LevelsRunFromStoredToSmallest) {
    // 0 stores the rows (the largest file), 9 is the smallest of all levels on a smooth image;
    // in between speed is traded for size (not strictly monotonic on every picture: on noisy
    // frames the unfiltered rows of level 1 can be smaller than filtered ones).
    const Picture p = pictures()[1];
    const std::vector<const std::uint8_t*> rows = rowTable(p);
    PngEncoder encoder;
    std::vector<std::size_t> sizes;
    for (int level = 0; level <= 9; ++level)
        sizes.push_back(encoder.encode(rows.data(), p.width, p.height, pngSettingsForLevel(level)).size());
    for (int level = 1; level <= 9; ++level) {
        EXPECT_LT(sizes[level], sizes[0]) << "--png-level " << level;
        EXPECT_GE(sizes[level], sizes[9]) << "--png-level " << level;
    }
    EXPECT_GT(sizes[0], p.rgba.size());  // stored: every byte plus the filter bytes
}
