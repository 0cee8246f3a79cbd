// PNG decoding (image/PngDecode through loadImageFile): libpng set up as the WebGL upload of an
// <img>. The fixtures are written here with libpng's writer in each colour type, so each test
// knows the exact pixels (PNG is lossless: every value must come back exactly).
#include <gtest/gtest.h>

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <png.h>
#include <zlib.h>

#include "TestFolder.h"
#include "image/ImageFile.h"
#include "image/PngDecode.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {
using TempFolder = toyhost::testing::TestFolder;

struct PngSpec {
    int colorType = PNG_COLOR_TYPE_RGB;
    int bitDepth = 8;
    bool interlaced = false;
    std::vector<png_color> palette;
    std::vector<png_byte> paletteAlpha;  // tRNS for a palette
    const png_color_16* transparent = nullptr;  // tRNS for grey / RGB
};

// Writes rows (top first, already packed for the colour type and depth; 16-bit big-endian).
void writePngFile(const fs::path& file, int width, int height, const std::vector<std::vector<png_byte>>& rows,
                  const PngSpec& spec) {
    std::FILE* out = std::fopen(file.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(out);
        FAIL() << "libpng could not write the fixture";
    }
    png_init_io(png, out);
    png_set_IHDR(png, info, width, height, spec.bitDepth, spec.colorType,
                 spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!spec.palette.empty()) png_set_PLTE(png, info, spec.palette.data(), static_cast<int>(spec.palette.size()));
    if (!spec.paletteAlpha.empty())
        png_set_tRNS(png, info, spec.paletteAlpha.data(), static_cast<int>(spec.paletteAlpha.size()), nullptr);
    if (spec.transparent) png_set_tRNS(png, info, nullptr, 0, const_cast<png_color_16*>(spec.transparent));
    png_set_gAMA(png, info, 1.0);  // a gamma the browser's WebGL upload must not apply
    png_write_info(png, info);
    std::vector<png_bytep> pointers;
    for (const auto& row : rows) pointers.push_back(const_cast<png_bytep>(row.data()));
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(out);
}

// Pixel (x, y) of a decoded image, y counted from the TOP row as in the file.
std::vector<int> pixel(const Image8& image, int x, int y) {
    const std::uint8_t* p = image.rgba.data() + (static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 4;
    return {p[0], p[1], p[2], p[3]};
}

std::vector<std::uint8_t> readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<std::streamsize>(bytes.size()));
}
}  // namespace

// A 2-bit palette with a tRNS chunk: indices become their colours, tRNS their alphas (255 past
// its end); the file's gAMA is not applied; rows come back bottom first.
TEST(PngDecode, PaletteWithTransparencyExpandsExactly) {
    TempFolder folder;
    PngSpec spec;
    spec.colorType = PNG_COLOR_TYPE_PALETTE;
    spec.bitDepth = 2;
    spec.palette = {{10, 20, 30}, {200, 100, 50}, {0, 255, 0}, {7, 8, 9}};
    spec.paletteAlpha = {0, 128};
    // 4x2: top row indices 0 1 2 3, bottom row 3 2 1 0 (2 bits each, first pixel in the high bits).
    writePngFile(folder.path / "palette.png", 4, 2, {{0b00011011}, {0b11100100}}, spec);
    const Result<Image8> image = loadImageFile(folder.path / "palette.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    EXPECT_EQ(pixel(*image, 0, 0), (std::vector<int>{10, 20, 30, 0}));
    EXPECT_EQ(pixel(*image, 1, 0), (std::vector<int>{200, 100, 50, 128}));
    EXPECT_EQ(pixel(*image, 2, 0), (std::vector<int>{0, 255, 0, 255}));
    EXPECT_EQ(pixel(*image, 3, 0), (std::vector<int>{7, 8, 9, 255}));
    EXPECT_EQ(pixel(*image, 0, 1), (std::vector<int>{7, 8, 9, 255}));
    EXPECT_EQ(pixel(*image, 3, 1), (std::vector<int>{10, 20, 30, 0}));
}

// 16-bit RGBA keeps each channel's high byte (0x12AB -> 0x12: cut, not rounded), as stb did.
TEST(PngDecode, SixteenBitChannelsKeepTheirHighByte) {
    TempFolder folder;
    PngSpec spec;
    spec.colorType = PNG_COLOR_TYPE_RGB_ALPHA;
    spec.bitDepth = 16;
    writePngFile(folder.path / "deep.png", 1, 1, {{0x12, 0xAB, 0xFF, 0xFF, 0x00, 0x80, 0x7F, 0xC0}}, spec);
    const Result<Image8> image = loadImageFile(folder.path / "deep.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    EXPECT_EQ(pixel(*image, 0, 0), (std::vector<int>{0x12, 0xFF, 0x00, 0x7F}));
}

// An RGB tRNS colour becomes alpha 0 on exactly that colour; interlaced files are de-interlaced.
TEST(PngDecode, RgbTransparentColourAndInterlacingComeBackExactly) {
    TempFolder folder;
    const int w = 9, h = 7;  // odd sizes: every Adam7 pass is partial
    std::vector<std::vector<png_byte>> rows;
    for (int y = 0; y < h; ++y) {
        rows.emplace_back();
        for (int x = 0; x < w; ++x)
            rows.back().insert(rows.back().end(), {static_cast<png_byte>(x * 20), static_cast<png_byte>(y * 30),
                                                   static_cast<png_byte>((x + y) % 2 ? 77 : 5)});
    }
    png_color_16 key{};
    key.red = 40;  // pixel (2, 1): 40, 30, (2+1)%2 -> 77
    key.green = 30;
    key.blue = 77;
    for (bool interlaced : {false, true}) {
        SCOPED_TRACE(interlaced ? "interlaced" : "not interlaced");
        PngSpec spec;
        spec.interlaced = interlaced;
        spec.transparent = &key;
        writePngFile(folder.path / "rgb.png", w, h, rows, spec);
        const Result<Image8> image = loadImageFile(folder.path / "rgb.png");
        ASSERT_TRUE(image.ok()) << image.error().text();
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const int alpha = (x == 2 && y == 1) ? 0 : 255;
                ASSERT_EQ(pixel(*image, x, y), (std::vector<int>{x * 20, y * 30, (x + y) % 2 ? 77 : 5, alpha}))
                    << x << "," << y;
            }
    }
}

// A few hundred bytes that declare 16000x16000: the data cannot hold that many pixels even at
// deflate's best ratio, so the file is refused before 1 GB is allocated for it.
TEST(PngDecode, ASmallFileDeclaringAHugeImageIsRefusedBeforeAllocating) {
    TempFolder folder;
    PngSpec spec;
    writePngFile(folder.path / "small.png", 4, 4, std::vector<std::vector<png_byte>>(4, std::vector<png_byte>(12, 9)), spec);
    std::vector<std::uint8_t> bytes = readBytes(folder.path / "small.png");
    // IHDR's width and height (bytes 16..23), and its CRC (over type and data, bytes 12..28).
    for (int k : {16, 20}) {
        bytes[k] = 0;
        bytes[k + 1] = 0;
        bytes[k + 2] = 0x3E;
        bytes[k + 3] = 0x80;  // 16000
    }
    const uLong crc = crc32(0L, bytes.data() + 12, 17);
    for (int k = 0; k < 4; ++k) bytes[29 + k] = static_cast<std::uint8_t>(crc >> (24 - 8 * k));
    writeBytes(folder.path / "huge.png", bytes);
    const Result<Image8> image = loadImageFile(folder.path / "huge.png");
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().text().find("declares 16000x16000 but the file is too small to hold it"), std::string::npos)
        << image.error().text();
}

// A damaged critical chunk (IDAT's CRC) is an error naming the file, as in a browser, where the
// image does not load; stb decoded such files without looking at the CRC.
TEST(PngDecode, ADamagedImageChunkIsRefusedWithItsReason) {
    TempFolder folder;
    writePngFile(folder.path / "ok.png", 4, 4, std::vector<std::vector<png_byte>>(4, std::vector<png_byte>(12, 9)), {});
    std::vector<std::uint8_t> bytes = readBytes(folder.path / "ok.png");
    const std::string text(bytes.begin(), bytes.end());
    const std::size_t idat = text.find("IDAT");
    ASSERT_NE(idat, std::string::npos);
    bytes[idat + 6] ^= 0xFF;  // inside the compressed data
    writeBytes(folder.path / "bad.png", bytes);
    const Result<Image8> image = loadImageFile(folder.path / "bad.png");
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().text().find((folder.path / "bad.png").string()), std::string::npos) << image.error().text();
    EXPECT_NE(image.error().text().find("cannot decode image"), std::string::npos) << image.error().text();
}

// A file cut after its image data (no IEND) still shows, with every row.
TEST(PngDecode, AFileMissingOnlyItsEndChunkDecodes) {
    TempFolder folder;
    writePngFile(folder.path / "ok.png", 4, 4, std::vector<std::vector<png_byte>>(4, std::vector<png_byte>(12, 9)), {});
    std::vector<std::uint8_t> bytes = readBytes(folder.path / "ok.png");
    const std::string text(bytes.begin(), bytes.end());
    ASSERT_EQ(text.rfind("IEND"), bytes.size() - 8);
    bytes.resize(bytes.size() - 12);
    writeBytes(folder.path / "no-iend.png", bytes);
    const Result<Image8> image = loadImageFile(folder.path / "no-iend.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    EXPECT_EQ(pixel(*image, 3, 3), (std::vector<int>{9, 9, 9, 255}));
}

// A PNG decode stops too when it outlasts the time limit (checked after every row): with no time at
// all a small image is refused, naming the file; with the default limit it decodes.
TEST(PngDecode, ADecodeThatOutlastsItsTimeLimitIsStopped) {
    TempFolder folder;
    const fs::path file = folder.path / "grey.png";
    writePngFile(file, 8, 4, std::vector<std::vector<png_byte>>(4, std::vector<png_byte>(8 * 3, 90)), {});
    const std::vector<std::uint8_t> bytes = readBytes(file);
    DecodeLimits none;
    none.maxSeconds = 0;
    const Result<Image8> stopped = decodePng(bytes, none, file.string());
    ASSERT_FALSE(stopped.ok());
    EXPECT_EQ(stopped.error().first().code, Code::ImageDecode);
    EXPECT_EQ(stopped.error().first().file, file.string());
    EXPECT_NE(stopped.error().text().find("longer than the 0 s of CPU time one image may take (stopped in a 8x4 PNG)"), std::string::npos)
        << stopped.error().text();
    EXPECT_TRUE(decodePng(bytes, DecodeLimits{}, file.string()).ok());
}
