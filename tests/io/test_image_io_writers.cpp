// ImageWriters: PNG/EXR round trips, row order, and atomic writes that leave nothing behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <unistd.h>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfPreviewImage.h>

#include "LibpngDecode.h"
#include "TestFolder.h"
#include "image/ImageWriters.h"

#include <memory>

using namespace toyhost;
namespace fs = std::filesystem;

namespace {
using TempFolder = toyhost::testing::TestFolder;

// Bottom-up RGBA8 where every pixel is distinct and the bottom row differs from the top row.
std::vector<std::uint8_t> gradient8(int width, int height) {
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int value : {x * 40, y * 50, x * 7 + y * 13, 255 - y * 30})
                rgba.push_back(static_cast<std::uint8_t>(value));
    return rgba;
}

std::vector<char> fileBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::ptrdiff_t findFloat(const std::vector<char>& bytes, float value) {
    char pattern[sizeof value];
    std::memcpy(pattern, &value, sizeof value);
    const auto it = std::search(bytes.begin(), bytes.end(), std::begin(pattern), std::end(pattern));
    return it == bytes.end() ? -1 : it - bytes.begin();
}
}  // namespace

TEST(ImageIo, FlipRowsReversesRowOrder) {
    std::vector<int> rows = {1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3};  // three 1-pixel rows
    std::vector<int> copy;
    copyFlipped(std::span<const int>(rows), 1, 3, copy);
    EXPECT_EQ(copy, (std::vector<int>{3, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1}));
    flipRows(std::span<int>(rows), 1, 3);
    EXPECT_EQ(rows, copy);
    std::vector<int> four = {1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4};  // an even row count
    flipRows(std::span<int>(four), 1, 4);
    EXPECT_EQ(four, (std::vector<int>{4, 4, 4, 4, 3, 3, 3, 3, 2, 2, 2, 2, 1, 1, 1, 1}));
}

TEST(ImageIo, PngRoundTripKeepsPixelsAndPutsTheTopRowFirst) {
    TempFolder folder;
    const int width = 5, height = 4;
    const std::vector<std::uint8_t> bottomUp = gradient8(width, height);
    for (int level : {0, 1, 9}) {
        const fs::path file = folder.path / ("frame" + std::to_string(level) + ".png");
        const Status written = writePng(file, width, height, bottomUp, level);
        ASSERT_TRUE(written.ok()) << written.error().text();
        // Read back (bottom row first, like every image in memory): the same pixels.
        const Result<Image8> read = readPng(file);
        ASSERT_TRUE(read.ok()) << read.error().text();
        ASSERT_EQ(read->width, width);
        ASSERT_EQ(read->height, height);
        EXPECT_EQ(read->rgba, bottomUp) << "level " << level;
        // In the file itself (decoded by libpng's simplified reader as stored, top row first) row 0
        // is the input's last row: the top of the image.
        std::ifstream in(file, std::ios::binary);
        const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        int w = 0, h = 0;
        const std::vector<std::uint8_t> raw = toyhost::testing::libpngDecode(bytes, w, h);
        ASSERT_EQ(raw.size(), bottomUp.size());
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width * 4; ++x)
                ASSERT_EQ(raw[static_cast<std::size_t>(y * width * 4 + x)],
                          bottomUp[static_cast<std::size_t>((height - 1 - y) * width * 4 + x)])
                    << "level " << level << " row " << y;
    }
    EXPECT_EQ(folder.files().size(), 3u);
}

TEST(ImageIo, ExrRoundTripIsBitExactIn32BitFloat) {
    TempFolder folder;
    const int width = 3, height = 2;
    std::vector<float> bottomUp = {
        // bottom row
        0.0f, -3.5f, 1e10f, 1.0f, 0.125f, 1.0f / 3.0f, 65504.5f, 0.5f, 1e-30f, 2.0f, -0.0f, 0.25f,
        // top row
        12345.5f, 7.0f, 8.0f, 0.0f, std::numeric_limits<float>::infinity(), 0.1f, 0.2f, 0.3f, 4.0f,
        5.0f, 6.0f, 1.0f};
    const fs::path file = folder.path / "buffer.exr";
    const Status written = writeExr(file, width, height, bottomUp);
    ASSERT_TRUE(written.ok()) << written.error().text();

    const Result<ImageF32> read = readExr(file);
    ASSERT_TRUE(read.ok()) << read.error().text();
    ASSERT_EQ(read->width, width);
    ASSERT_EQ(read->height, height);
    ASSERT_EQ(read->rgba.size(), bottomUp.size());
    EXPECT_EQ(std::memcmp(read->rgba.data(), bottomUp.data(), bottomUp.size() * sizeof(float)), 0)
        << "values must survive unchanged (32-bit FLOAT channels, not half)";

    // In the file the top row is scanline 0, so its R value (12345.5) comes before the bottom
    // row's distinctive G value (-3.5). Uncompressed, so the raw floats are visible.
    const std::vector<char> bytes = fileBytes(file);
    const std::ptrdiff_t top = findFloat(bytes, 12345.5f), bottom = findFloat(bytes, -3.5f);
    ASSERT_GE(top, 0);
    ASSERT_GE(bottom, 0);
    EXPECT_LT(top, bottom);
}

TEST(ImageIo, RejectsBuffersThatDoNotMatchTheSize) {
    TempFolder folder;
    const std::vector<std::uint8_t> bytes(10);
    const Status png = writePng(folder.path / "a.png", 2, 2, bytes);
    ASSERT_FALSE(png.ok());
    EXPECT_NE(png.error().text().find("a.png"), std::string::npos);
    const std::vector<float> floats(15);
    EXPECT_FALSE(writeExr(folder.path / "a.exr", 2, 2, floats).ok());
    EXPECT_FALSE(writePng(folder.path / "b.png", 0, 0, {}).ok());
    EXPECT_FALSE(writePng(folder.path / "c.png", 1, 1, gradient8(1, 1), 10).ok());
    EXPECT_EQ(folder.files(), std::vector<std::string>{});
}

TEST(ImageIo, PngWiderThanLibpngReadsIsRefusedAndLeavesNothing) {
    TempFolder folder;
    // libpng's readers refuse widths over their 1,000,000 default user limit: such a file is
    // refused before anything is written.
    const int width = 1'000'001;
    const std::vector<std::uint8_t> row(static_cast<std::size_t>(width) * 4, 128);
    const Status written = writePng(folder.path / "wide.png", width, 1, row);
    ASSERT_FALSE(written.ok());
    EXPECT_NE(written.error().text().find("PNG encoding failed"), std::string::npos)
        << written.error().text();
    EXPECT_EQ(folder.files(), std::vector<std::string>{});
}

TEST(ImageIo, FailedRenameLeavesNoPartialAndKeepsTheTarget) {
    TempFolder folder;
    // The target is an existing folder: the data is written to a temporary file, the rename over
    // the folder fails, and the temporary file must be removed.
    const fs::path target = folder.path / "taken";
    fs::create_directories(target / "inside");
    std::ofstream(target / "inside" / "keep.txt") << "keep";
    const Status png = writePng(target, 2, 2, gradient8(2, 2));
    EXPECT_FALSE(png.ok());
    const std::vector<float> floats(2 * 2 * 4, 1.0f);
    EXPECT_FALSE(writeExr(target, 2, 2, floats).ok());
    EXPECT_EQ(folder.files(), std::vector<std::string>{"keep.txt"});
}

TEST(ImageIo, UncreatableFolderLeavesNothing) {
    TempFolder folder;
    std::ofstream(folder.path / "plainfile") << "x";
    const Status png =
        writePng(folder.path / "plainfile" / "sub" / "frame.png", 2, 2, gradient8(2, 2));
    ASSERT_FALSE(png.ok());
    const std::vector<float> floats(2 * 2 * 4, 1.0f);
    EXPECT_FALSE(writeExr(folder.path / "plainfile" / "frame.exr", 2, 2, floats).ok());
    EXPECT_EQ(folder.files(), std::vector<std::string>{"plainfile"});
}

TEST(ImageIo, ReadingMissingFilesNamesThePath) {
    TempFolder folder;
    const Result<ImageF32> exr = readExr(folder.path / "none.exr");
    ASSERT_FALSE(exr.ok());
    EXPECT_NE(exr.error().text().find("none.exr"), std::string::npos);
    EXPECT_NE(exr.error().text().find("file not found"), std::string::npos);
    const Result<Image8> png = readPng(folder.path / "none.png");
    ASSERT_FALSE(png.ok());
    EXPECT_NE(png.error().text().find("none.png"), std::string::npos);
}

TEST(ImageIo, ReadingAFileThatIsNotExrIsAnError) {
    TempFolder folder;
    std::ofstream(folder.path / "fake.exr") << "not an exr file";
    const Result<ImageF32> exr = readExr(folder.path / "fake.exr");
    ASSERT_FALSE(exr.ok());
    EXPECT_NE(exr.error().text().find("fake.exr"), std::string::npos);
}

TEST(ImageIo, EveryExrCompressionReadsBackLosslessOnesExactlyAndHalfWithinHalfPrecision) {
    TempFolder folder;
    const int width = 37, height = 21;  // odd sizes: partial blocks for b44 and dwa
    std::vector<float> rgba;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (float v : {x * 0.0371f, y * 1.37f - 3.0f, (x * y) % 7 * 0.25f, 1.0f / (1 + x + y)}) rgba.push_back(v);
    const std::vector<std::string> lossless = {"none", "rle", "zips", "zip", "piz"};
    for (bool half : {false, true}) {
        for (const std::string& name : {"none", "rle", "zips", "zip", "piz", "pxr24", "b44", "b44a", "dwaa", "dwab"}) {
            const std::optional<ExrCompression> compression = exrCompressionNamed(name);
            ASSERT_TRUE(compression) << name;
            EXPECT_EQ(exrCompressionName(*compression), name);
            const fs::path file = folder.path / (name + (half ? "_half" : "") + ".exr");
            const Status written = writeExr(file, width, height, rgba, nullptr, {*compression, half});
            ASSERT_TRUE(written.ok()) << written.error().text();
            const Result<ImageF32> read = readExr(file);
            ASSERT_TRUE(read.ok()) << read.error().text();
            ASSERT_EQ(read->rgba.size(), rgba.size());
            const bool exact = std::find(lossless.begin(), lossless.end(), name) != lossless.end();
            for (std::size_t i = 0; i < rgba.size(); ++i) {
                if (exact && !half) {
                    ASSERT_EQ(read->rgba[i], rgba[i]) << name << " value " << i;
                } else if (exact && half) {
                    // Half keeps 11 significant bits: round to nearest is within 2^-11 relative.
                    ASSERT_NEAR(read->rgba[i], rgba[i], std::abs(rgba[i]) * (1.0f / 2048.0f) + 1e-7f)
                        << name << " half, value " << i;
                } else if (name == "pxr24" && !half) {
                    ASSERT_NEAR(read->rgba[i], rgba[i], std::abs(rgba[i]) * (1.0f / 32768.0f) + 1e-7f) << name;
                }
                // b44/b44a/dwaa/dwab are lossy: read back, sizes right; no bound is promised here.
            }
        }
    }
    EXPECT_FALSE(exrCompressionNamed("zip9"));
}

namespace {
// An EXR with a 2x2 preview image, written by OpenEXR itself; returns the file's bytes.
std::string exrWithPreview(const fs::path& file) {
    Imf::Header header(4, 4);
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    header.setPreviewImage(Imf::PreviewImage(2, 2));
    std::vector<float> red(16, 0.5f);
    Imf::FrameBuffer frame;
    frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(red.data()), sizeof(float), 4 * sizeof(float)));
    {
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(4);
    }
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
}  // namespace

// OpenEXR allocates a preview image from the width and height in its value, whatever size the
// attribute declares; and it reads fixed-size attributes by their type's size. Headers whose
// declarations disagree with what OpenEXR reads are refused before OpenEXR parses them.
TEST(ImageIo, ExrAttributesWhoseSizesDisagreeWithTheirValuesAreRefused) {
    TempFolder folder;
    const fs::path good = folder.path / "preview.exr";
    const std::string bytes = exrWithPreview(good);
    ASSERT_TRUE(readExr(good).ok()) << readExr(good).error().text();

    const std::size_t preview = bytes.find(std::string("preview\0preview\0", 16));
    ASSERT_NE(preview, std::string::npos);
    std::string huge = bytes;
    huge[preview + 16 + 4 + 2] = '\x01';  // width 2 -> 65538: 4 * 65538 * 2 + 8 bytes, not 24
    const fs::path hugeFile = folder.path / "huge-preview.exr";
    std::ofstream(hugeFile, std::ios::binary) << huge;

    const std::size_t window = bytes.find(std::string("displayWindow\0box2i\0", 20));
    ASSERT_NE(window, std::string::npos);
    std::string shortBox = bytes;
    shortBox[window + 20] = '\x0c';  // a box2i that declares 12 bytes (OpenEXR reads 16)
    const fs::path shortFile = folder.path / "short-box.exr";
    std::ofstream(shortFile, std::ios::binary) << shortBox;

    for (const fs::path& file : {hugeFile, shortFile}) {
        const Result<ImageF32> read = readExr(file);
        ASSERT_FALSE(read.ok()) << file;
        EXPECT_NE(read.error().text().find("an attribute's declared size does not match its type"), std::string::npos)
            << read.error().text();
    }
}
