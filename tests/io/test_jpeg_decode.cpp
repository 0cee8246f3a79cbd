// JPEG decoding (image/JpegDecode through loadImageFile): libjpeg-turbo set up as the browser's
// JPEG reader. The fixtures are encoded here with libjpeg's encoder, so each test knows the picture
// the file holds; decoded values are checked against it within JPEG's error at quality 100.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <jpeglib.h>

#include "TestFolder.h"
#include "image/ImageFile.h"
#include "image/JpegDecode.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {

struct Encoding {
    J_COLOR_SPACE space = JCS_RGB;  // of `samples`: JCS_RGB (3), JCS_GRAYSCALE (1), JCS_CMYK (4)
    bool progressive = false;
    bool subsampled = false;        // 4:2:0 chroma (libjpeg's default) instead of 4:4:4
};

int componentsOf(J_COLOR_SPACE space) { return space == JCS_GRAYSCALE ? 1 : space == JCS_CMYK ? 4 : 3; }

// Encodes `samples` (top row first, componentsOf(space) bytes a pixel) at quality 100.
std::vector<std::uint8_t> encodeJpeg(int width, int height, const std::vector<std::uint8_t>& samples,
                                     const Encoding& how) {
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);
    jpeg_create_compress(&info);
    unsigned char* out = nullptr;
    unsigned long outSize = 0;
    jpeg_mem_dest(&info, &out, &outSize);
    info.image_width = static_cast<JDIMENSION>(width);
    info.image_height = static_cast<JDIMENSION>(height);
    info.input_components = componentsOf(how.space);
    info.in_color_space = how.space;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 100, TRUE);
    if (!how.subsampled)
        for (int c = 0; c < info.num_components; ++c) info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
    if (how.progressive) jpeg_simple_progression(&info);
    jpeg_start_compress(&info, TRUE);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(info.input_components);
    while (info.next_scanline < info.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(samples.data() + info.next_scanline * rowBytes);
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::vector<std::uint8_t> file(out, out + outSize);
    std::free(out);
    return file;
}

fs::path writeFile(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                static_cast<std::streamsize>(bytes.size()));
    return file;
}

// The offset of the first SOFn marker's height field (FFC0 / FFC2: length, precision, height, width).
std::size_t frameHeaderAt(const std::vector<std::uint8_t>& file) {
    for (std::size_t i = 2; i + 9 < file.size(); ++i)
        if (file[i] == 0xFF && (file[i + 1] == 0xC0 || file[i + 1] == 0xC2)) return i + 5;
    ADD_FAILURE() << "no SOF0/SOF2 marker";
    return 0;
}

void setDeclaredSize(std::vector<std::uint8_t>& file, int width, int height) {
    const std::size_t at = frameHeaderAt(file);
    file[at] = static_cast<std::uint8_t>(height >> 8);
    file[at + 1] = static_cast<std::uint8_t>(height & 255);
    file[at + 2] = static_cast<std::uint8_t>(width >> 8);
    file[at + 3] = static_cast<std::uint8_t>(width & 255);
}

void append(std::vector<std::uint8_t>& bytes, std::initializer_list<int> values) {
    for (int v : values) bytes.push_back(static_cast<std::uint8_t>(v));
}

// A grey baseline JPEG coded as tightly as Huffman coding allows: one symbol in each table (DC
// difference 0, AC end of block), each a 1-bit code, so a block costs 2 bits. The scan holds
// `codedBlocks` blocks (zero bits: mid-grey); libjpeg decodes any blocks past them as the same grey.
std::vector<std::uint8_t> tightGreyJpeg(int width, int height, std::size_t codedBlocks) {
    std::vector<std::uint8_t> bytes;
    append(bytes, {0xFF, 0xD8, 0xFF, 0xDB, 0, 67, 0});  // SOI, DQT: table 0 of 8-bit ones
    bytes.insert(bytes.end(), 64, 1);
    append(bytes, {0xFF, 0xC0, 0, 11, 8, height >> 8, height & 255, width >> 8, width & 255, 1, 1, 0x11, 0});
    append(bytes, {0xFF, 0xC4, 0, 20, 0x00, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00});  // DC: "0" = 0
    append(bytes, {0xFF, 0xC4, 0, 20, 0x10, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00});  // AC: "0" = EOB
    append(bytes, {0xFF, 0xDA, 0, 8, 1, 1, 0x00, 0, 63, 0});
    bytes.insert(bytes.end(), (codedBlocks * 2 + 7) / 8, 0);
    append(bytes, {0xFF, 0xD9});
    return bytes;
}

// A grey progressive JPEG: a first DC scan coding every block with a 1-bit code (DC difference 0),
// then `emptyScans` AC scans without data, each of which libjpeg still walks block by block.
std::vector<std::uint8_t> greyJpegWithEmptyScans(int side, int emptyScans) {
    std::vector<std::uint8_t> bytes;
    append(bytes, {0xFF, 0xD8, 0xFF, 0xDB, 0, 67, 0});
    bytes.insert(bytes.end(), 64, 1);
    append(bytes, {0xFF, 0xC2, 0, 11, 8, side >> 8, side & 255, side >> 8, side & 255, 1, 1, 0x11, 0});
    append(bytes, {0xFF, 0xC4, 0, 20, 0x00, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00});
    append(bytes, {0xFF, 0xC4, 0, 20, 0x10, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00});
    append(bytes, {0xFF, 0xDA, 0, 8, 1, 1, 0x00, 0, 0, 0});
    const std::size_t blocks = std::size_t((side + 7) / 8) * std::size_t((side + 7) / 8);
    bytes.insert(bytes.end(), (blocks + 7) / 8, 0);
    for (int i = 0; i < emptyScans; ++i) append(bytes, {0xFF, 0xDA, 0, 8, 1, 1, 0x00, 1, 63, 0});
    append(bytes, {0xFF, 0xD9});
    return bytes;
}

// Pixel (x, y) of a decoded image, y counted from the TOP row as in the file.
const std::uint8_t* pixelFromTop(const Image8& image, int x, int y) {
    return image.rgba.data() + (static_cast<std::size_t>(image.height - 1 - y) * image.width + x) * 4;
}

using TempFolder = toyhost::testing::TestFolder;

}  // namespace

// Top half red, bottom half blue, 4:4:4 at quality 100: the decoded rows are bottom first (as GL
// uploads them), every alpha is 255, and the colours come back within JPEG's error.
TEST(JpegDecode, RgbRowsComeBackBottomFirstWithOpaqueAlpha) {
    TempFolder folder;
    const int w = 16, h = 16;
    std::vector<std::uint8_t> rgb;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) rgb.insert(rgb.end(), y < h / 2 ? std::initializer_list<std::uint8_t>{255, 0, 0}
                                                                 : std::initializer_list<std::uint8_t>{0, 0, 255});
    for (bool progressive : {false, true}) {
        SCOPED_TRACE(progressive ? "progressive" : "baseline");
        const fs::path file = writeFile(folder.path / "halves.jpg", encodeJpeg(w, h, rgb, {JCS_RGB, progressive, false}));
        const Result<Image8> image = loadImageFile(file);
        ASSERT_TRUE(image.ok()) << image.error().text();
        ASSERT_EQ(image->width, w);
        ASSERT_EQ(image->height, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::uint8_t* p = pixelFromTop(*image, x, y);
                const int expectR = y < h / 2 ? 255 : 0, expectB = y < h / 2 ? 0 : 255;
                ASSERT_NEAR(p[0], expectR, 6) << x << "," << y;
                ASSERT_NEAR(p[1], 0, 6) << x << "," << y;
                ASSERT_NEAR(p[2], expectB, 6) << x << "," << y;
                ASSERT_EQ(p[3], 255);
            }
    }
}

// A one-component JPEG becomes R = G = B = grey, alpha 255, as the browser's upload of it.
TEST(JpegDecode, GreyExpandsToEqualChannels) {
    TempFolder folder;
    const int w = 32, h = 8;
    std::vector<std::uint8_t> grey;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) grey.push_back(static_cast<std::uint8_t>(x * 8));
    const Result<Image8> image =
        loadImageFile(writeFile(folder.path / "grey.jpg", encodeJpeg(w, h, grey, {JCS_GRAYSCALE, false, false})));
    ASSERT_TRUE(image.ok()) << image.error().text();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* p = pixelFromTop(*image, x, y);
            ASSERT_EQ(p[0], p[1]);
            ASSERT_EQ(p[1], p[2]);
            ASSERT_EQ(p[3], 255);
            ASSERT_NEAR(p[0], x * 8, 3) << x << "," << y;
        }
}

// libjpeg writes CMYK with an Adobe marker, whose values are inverted: the browser's reader turns
// them into R = C*K/255 (and G, B alike). C=200 M=100 Y=50 K=128 gives about (100, 50, 25).
TEST(JpegDecode, AdobeCmykBecomesRgbAsTheBrowserDoes) {
    TempFolder folder;
    const int w = 16, h = 16;
    std::vector<std::uint8_t> cmyk;
    for (int i = 0; i < w * h; ++i) cmyk.insert(cmyk.end(), {200, 100, 50, 128});
    const Result<Image8> image =
        loadImageFile(writeFile(folder.path / "cmyk.jpg", encodeJpeg(w, h, cmyk, {JCS_CMYK, false, false})));
    ASSERT_TRUE(image.ok()) << image.error().text();
    for (int i = 0; i < w * h; ++i) {
        const std::uint8_t* p = image->rgba.data() + 4 * i;
        ASSERT_NEAR(p[0], 200 * 128 / 255, 3);
        ASSERT_NEAR(p[1], 100 * 128 / 255, 3);
        ASSERT_NEAR(p[2], 50 * 128 / 255, 3);
        ASSERT_EQ(p[3], 255);
    }
}

// The fuzz seeds cover the layouts users' textures come in (baseline, progressive, restart
// intervals, 4:2:0, 4:2:2, 4:4:4, grey): each decodes to the size its header declares.
TEST(JpegDecode, EveryLayoutOfTheFuzzSeedsDecodes) {
    const fs::path dir = fs::path(TOYHOST_SOURCE_DIR) / "tests/fuzz/seeds/fuzz_image";
    int decoded = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".jpg") continue;
        SCOPED_TRACE(entry.path().filename().string());
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const std::size_t at = frameHeaderAt(bytes);
        const int height = bytes[at] << 8 | bytes[at + 1], width = bytes[at + 2] << 8 | bytes[at + 3];
        const Result<Image8> image = loadImageFile(entry.path());
        ASSERT_TRUE(image.ok()) << image.error().text();
        EXPECT_EQ(image->width, width);
        EXPECT_EQ(image->height, height);
        EXPECT_EQ(image->rgba.size(), std::size_t(width) * std::size_t(height) * 4);
        ++decoded;
    }
    EXPECT_GE(decoded, 7);
}

// A file cut short is refused with a reason naming it (libjpeg alone would fill the rest grey).
TEST(JpegDecode, ATruncatedFileIsRefusedWithItsName) {
    TempFolder folder;
    const int w = 64, h = 64;
    std::vector<std::uint8_t> rgb;
    for (int i = 0; i < w * h; ++i) rgb.insert(rgb.end(), {static_cast<std::uint8_t>(i * 7), static_cast<std::uint8_t>(i * 13), 90});
    for (bool progressive : {false, true}) {
        SCOPED_TRACE(progressive ? "progressive" : "baseline");
        std::vector<std::uint8_t> bytes = encodeJpeg(w, h, rgb, {JCS_RGB, progressive, true});
        bytes.resize(bytes.size() * 2 / 3);
        const fs::path file = writeFile(folder.path / "cut.jpg", bytes);
        const Result<Image8> image = loadImageFile(file);
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().first().code, Code::ImageDecode);
        EXPECT_NE(image.error().text().find(file.string()), std::string::npos) << image.error().text();
        EXPECT_NE(image.error().text().find("truncated"), std::string::npos) << image.error().text();
    }
}

// A side over the texture limit is refused from the header, before anything is decoded.
TEST(JpegDecode, ASideOverTheTextureLimitIsRefusedFromTheHeader) {
    TempFolder folder;
    std::vector<std::uint8_t> bytes = encodeJpeg(8, 8, std::vector<std::uint8_t>(8 * 8 * 3, 128), {});
    setDeclaredSize(bytes, 20000, 8);
    const Result<Image8> image = loadImageFile(writeFile(folder.path / "wide.jpg", bytes));
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().first().code, Code::ImageTooLarge);
    EXPECT_NE(image.error().text().find("20000x8"), std::string::npos) << image.error().text();
}

// A 16000x16000 progressive JPEG's DCT coefficients alone need 1.5 GB: libjpeg's working memory is
// capped, so the file is refused instead of filling memory. (Comment segments make the file large
// enough for the blocks it declares, which a smaller file is refused for before this.)
TEST(JpegDecode, AHugeDeclaredProgressiveImageIsRefusedNotAllocated) {
    TempFolder folder;
    std::vector<std::uint8_t> bytes = encodeJpeg(16, 16, std::vector<std::uint8_t>(16 * 16 * 3, 60), {JCS_RGB, true, false});
    setDeclaredSize(bytes, 16000, 16000);
    std::vector<std::uint8_t> comment{0xFF, 0xFE, 0xFF, 0xFF};
    comment.resize(2 + 0xFFFF, ' ');
    for (int i = 0; i < 24; ++i) bytes.insert(bytes.begin() + 2, comment.begin(), comment.end());
    const Result<Image8> image = loadImageFile(writeFile(folder.path / "huge.jpg", bytes));
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().first().code, Code::ImageDecode);
    EXPECT_NE(image.error().text().find("needs more than 512 MiB of working memory"), std::string::npos)
        << image.error().text();
    EXPECT_NE(image.error().text().find("16000x16000"), std::string::npos) << image.error().text();
}

// Huffman coding spends at least a bit on every 8x8 block: a file with fewer bits than the blocks
// its header declares cannot hold its picture. The most tightly coded file (2 bits a block)
// decodes; the same data declaring four times the blocks is refused from the header, naming the
// file and the sizes (libjpeg alone fills the rest with grey, after allocating the whole picture).
TEST(JpegDecode, AFileWithFewerBitsThanItsDeclaredBlocksIsRefusedFromTheHeader) {
    TempFolder folder;
    const Result<Image8> tight = loadImageFile(writeFile(folder.path / "tight.jpg", tightGreyJpeg(1024, 1024, 128 * 128)));
    ASSERT_TRUE(tight.ok()) << tight.error().text();
    EXPECT_EQ(tight->width, 1024);
    EXPECT_EQ(pixelFromTop(*tight, 1000, 1000)[0], 128);

    const fs::path file = writeFile(folder.path / "claims-more.jpg", tightGreyJpeg(2048, 2048, 128 * 128));
    const Result<Image8> image = loadImageFile(file);
    ASSERT_FALSE(image.ok()) << "decoded " << image->width << "x" << image->height;
    EXPECT_EQ(image.error().first().code, Code::ImageDecode);
    const std::string text = image.error().text();
    EXPECT_NE(text.find(file.string()), std::string::npos) << text;
    EXPECT_NE(text.find("2048x2048"), std::string::npos) << text;
    EXPECT_NE(text.find("65536 blocks"), std::string::npos) << text;
    EXPECT_NE(text.find("at least 8192 bytes"), std::string::npos) << text;
    EXPECT_NE(text.find("the file has " + std::to_string(fs::file_size(file)) + " bytes"), std::string::npos) << text;
}

// The report's case: a couple of kilobytes of colour JPEG (64x48 of data) whose header claims
// 16000x16000 was decoded into a 1 GB picture. It is refused before anything is allocated.
TEST(JpegDecode, A2KBFileDeclaring16000x16000IsRefusedBeforeAllocating) {
    TempFolder folder;
    std::vector<std::uint8_t> rgb;
    for (int i = 0; i < 64 * 48; ++i) rgb.insert(rgb.end(), {static_cast<std::uint8_t>(i * 7), static_cast<std::uint8_t>(i), 90});
    for (bool progressive : {false, true}) {
        SCOPED_TRACE(progressive ? "progressive" : "baseline");
        std::vector<std::uint8_t> bytes = encodeJpeg(64, 48, rgb, {JCS_RGB, progressive, true});
        setDeclaredSize(bytes, 16000, 16000);
        const Result<Image8> image = loadImageFile(writeFile(folder.path / "claims-16000.jpg", bytes));
        ASSERT_FALSE(image.ok());
        EXPECT_EQ(image.error().first().code, Code::ImageDecode);
        EXPECT_NE(image.error().text().find("declares 16000x16000, 6000000 blocks"), std::string::npos)
            << image.error().text();
    }
}

// Every scan of a progressive JPEG makes the decoder pass over the picture again, and a scan can be
// a dozen bytes: 330 KB of 20000 scans kept libjpeg busy for minutes. 500 scans (the limit) decode;
// one more is refused as soon as the decoder reaches it, naming the file.
TEST(JpegDecode, AProgressiveJpegOfMoreScansThanTheLimitIsRefused) {
    TempFolder folder;
    ASSERT_EQ(DecodeLimits{}.maxScans, 500);
    const Result<Image8> atLimit = loadImageFile(writeFile(folder.path / "500.jpg", greyJpegWithEmptyScans(64, 499)));
    ASSERT_TRUE(atLimit.ok()) << atLimit.error().text();
    EXPECT_EQ(pixelFromTop(*atLimit, 10, 10)[0], 128);

    const fs::path file = writeFile(folder.path / "bomb.jpg", greyJpegWithEmptyScans(2048, 20000));
    const Result<Image8> image = loadImageFile(file);
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().first().code, Code::ImageDecode);
    EXPECT_NE(image.error().text().find(file.string()), std::string::npos) << image.error().text();
    EXPECT_NE(image.error().text().find("more than 500 scans"), std::string::npos) << image.error().text();
}

// Decoding stops when it outlasts the time limit (a file of slow scans under the scan limit, an
// arithmetic-coded bomb): with no time at all, even a small image is refused, naming the file and
// where it stopped; with the default limit it decodes.
TEST(JpegDecode, ADecodeThatOutlastsItsTimeLimitIsStopped) {
    std::vector<std::uint8_t> rgb(32 * 32 * 3, 77);
    for (bool progressive : {false, true}) {
        SCOPED_TRACE(progressive ? "progressive" : "baseline");
        const std::vector<std::uint8_t> bytes = encodeJpeg(32, 32, rgb, {JCS_RGB, progressive, true});
        DecodeLimits none;
        none.maxSeconds = 0;
        const Result<Image8> stopped = decodeJpeg(bytes, none, "slow.jpg");
        ASSERT_FALSE(stopped.ok());
        EXPECT_EQ(stopped.error().first().code, Code::ImageDecode);
        EXPECT_EQ(stopped.error().first().file, "slow.jpg");
        EXPECT_NE(stopped.error().text().find("longer than the 0 s of CPU time one image may take (stopped in scan 1 of a 32x32 JPEG)"),
                  std::string::npos)
            << stopped.error().text();
        EXPECT_TRUE(decodeJpeg(bytes, DecodeLimits{}, "slow.jpg").ok());
    }
}
