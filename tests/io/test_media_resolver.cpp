// MediaResolver and loadImageFile: overrides, search folders, stand-ins, and the WebGL-style
// decode.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "TestFolder.h"
#include "image/ImageWriters.h"
#include "image/ImageFile.h"
#include "media/MediaResolver.h"
#include "manifest/StockMedia.h"
#include "media/StandIns.h"

using namespace toyhost;
namespace fs = std::filesystem;

namespace {
using TempFolder = toyhost::testing::TestFolder;

// A width x height PNG whose every pixel is `value` (R=G=B=value, A=255).
fs::path writeSolidPng(const fs::path& file, int width, int height, std::uint8_t value) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width * height * 4), value);
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    EXPECT_TRUE(writePng(file, width, height, rgba).ok());
    return file;
}

void writeBytes(const fs::path& file, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
}

const std::string kAbstract3Hash =
    "8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683";
const std::string kAbstract3 = "/media/a/" + kAbstract3Hash + ".jpg";

// Hand-made PNGs: 2x2 grey {0, 64 / 128, 255}, 2x1 RGB {(10,20,30), (40,50,60)}, 1x1 grey+alpha
// (90, 7).
const std::vector<std::uint8_t> kGreyPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x00, 0x00, 0x00, 0x00, 0x57,
    0xdd, 0x52, 0xf8, 0x00, 0x00, 0x00, 0x0e, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60,
    0x70, 0x60, 0x68, 0xf8, 0x0f, 0x00, 0x03, 0x05, 0x01, 0xc0, 0x4e, 0x33, 0x5b, 0xe9, 0x00,
    0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
const std::vector<std::uint8_t> kRgbPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
    0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x02, 0x00, 0x00, 0x00, 0x7b,
    0x40, 0xe8, 0xdd, 0x00, 0x00, 0x00, 0x0f, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xe0,
    0x12, 0x91, 0xd3, 0x30, 0xb2, 0x01, 0x00, 0x02, 0x37, 0x00, 0xd3, 0x5b, 0x56, 0x51, 0xd8,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
const std::vector<std::uint8_t> kGreyAlphaPng = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x04, 0x00, 0x00,
    0x00, 0xb5, 0x1c, 0x0c, 0x02, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x88, 0x62, 0x07, 0x00, 0x00, 0xbe, 0x00, 0x62, 0x7b, 0x3f, 0x78, 0x87,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
}  // namespace

TEST(MediaImageFile, MissingFileErrorNamesThePath) {
    TempFolder folder;
    const fs::path missing = folder.path / "nope.png";
    const Result<Image8> image = loadImageFile(missing);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().text().find(missing.string()), std::string::npos);
    EXPECT_NE(image.error().text().find("file not found"), std::string::npos);
}

TEST(MediaImageFile, UndecodableFileErrorGivesTheReason) {
    TempFolder folder;
    const fs::path junk = folder.path / "junk.png";
    writeBytes(junk, {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'});
    const Result<Image8> image = loadImageFile(junk);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().text().find(junk.string()), std::string::npos);
    EXPECT_NE(image.error().text().find("cannot decode"), std::string::npos);
}

// A JPEG whose Huffman table (DHT) is malformed, cut short or holding more than 256 codes, is
// refused with libjpeg's reason (stb_image, the decoder before, wrote past its table on the second).
TEST(MediaImageFile, JpegWithAMalformedHuffmanTableIsRefusedWithAReason) {
    TempFolder folder;
    const fs::path truncated = folder.path / "truncated.jpg";
    writeBytes(truncated, {0xFF, 0xD8, 0xFF, 0xC4, 0x00, 0x15, 0x01, 0xFF, 0xD9});
    std::vector<unsigned char> whole = {0xFF, 0xD8, 0xFF, 0xC4, 0x01, 0x13, 0x00};  // DHT of 275 bytes
    for (int k = 0; k < 16; ++k) whole.push_back(k < 2 ? 0xFF : 0x00);  // 510 codes
    whole.resize(whole.size() + 256, 0x01);
    whole.insert(whole.end(), {0xFF, 0xD9});
    const fs::path oversized = folder.path / "oversized.jpg";
    writeBytes(oversized, whole);
    for (const auto& [file, reason] : {std::pair{truncated, "truncated"}, std::pair{oversized, "Bogus Huffman table definition"}}) {
        const Result<Image8> image = loadImageFile(file);
        ASSERT_FALSE(image.ok()) << file;
        EXPECT_NE(image.error().text().find(reason), std::string::npos) << image.error().text();
        EXPECT_NE(image.error().text().find(file.string()), std::string::npos) << image.error().text();
    }
}

TEST(MediaImageFile, ExpandsGreyAndFillsAlphaLikeAWebGlUpload) {
    TempFolder folder;
    writeBytes(folder.path / "grey.png", kGreyPng);
    writeBytes(folder.path / "rgb.png", kRgbPng);
    writeBytes(folder.path / "greyAlpha.png", kGreyAlphaPng);

    const Result<Image8> grey = loadImageFile(folder.path / "grey.png");
    ASSERT_TRUE(grey.ok()) << grey.error().text();
    EXPECT_EQ(grey->width, 2);
    EXPECT_EQ(grey->height, 2);
    EXPECT_EQ(grey->rgba,
              (std::vector<std::uint8_t>{128, 128, 128, 255, 255, 255, 255, 255,  // bottom row first
                                         0, 0, 0, 255, 64, 64, 64, 255}));

    const Result<Image8> rgb = loadImageFile(folder.path / "rgb.png");
    ASSERT_TRUE(rgb.ok()) << rgb.error().text();
    EXPECT_EQ(rgb->rgba, (std::vector<std::uint8_t>{10, 20, 30, 255, 40, 50, 60, 255}));

    const Result<Image8> greyAlpha = loadImageFile(folder.path / "greyAlpha.png");
    ASSERT_TRUE(greyAlpha.ok()) << greyAlpha.error().text();
    EXPECT_EQ(greyAlpha->rgba, (std::vector<std::uint8_t>{90, 90, 90, 7}));  // not premultiplied
}

TEST(MediaResolver, OverrideWinsOverFoldersAndStandIns) {
    TempFolder folder;
    writeSolidPng(folder.path / (kAbstract3Hash + ".jpg"), 4, 4,
                  10);  // PNG bytes: decoded by content
    const fs::path mine = writeSolidPng(folder.path / "mine.png", 2, 3, 200);
    MediaResolver resolver;
    resolver.addSearchFolder(folder.path);
    resolver.setOverride("abstract 3", mine);  // any form of the id normalises to the same key

    for (const std::string& ref : {kAbstract3, kAbstract3Hash, std::string("Abstract 3")}) {
        const Result<ResolvedMedia> media = resolver.resolve(ref);
        ASSERT_TRUE(media.ok()) << media.error().text();
        EXPECT_FALSE(media->standIn);
        EXPECT_TRUE(media->notice.message.empty());
        EXPECT_EQ(media->image.width, 2) << ref;
        EXPECT_EQ(media->image.height, 3) << ref;
        EXPECT_EQ(media->image.rgba[0], 200) << ref;
    }
}

TEST(MediaResolver, BrokenOverrideIsAnErrorNotASilentStandIn) {
    TempFolder folder;
    MediaResolver resolver;
    resolver.setOverride(kAbstract3, folder.path / "missing.jpg");
    const Result<ResolvedMedia> media = resolver.resolve("Abstract 3");
    ASSERT_FALSE(media.ok());
    EXPECT_NE(media.error().text().find("missing.jpg"), std::string::npos);
    EXPECT_NE(media.error().text().find("Abstract 3"), std::string::npos);
}

TEST(MediaResolver, FindsRealFilesInSearchFoldersByHashOrName) {
    TempFolder byHash, byName, byTitle;
    writeSolidPng(byHash.path / (kAbstract3Hash + ".jpg"), 4, 4, 11);
    writeSolidPng(byName.path / "abstract_3.jpg", 4, 4, 22);
    writeSolidPng(byTitle.path / "Abstract 3.png", 4, 4, 33);
    const std::pair<const TempFolder*, int> cases[] = {
        {&byHash, 11}, {&byName, 22}, {&byTitle, 33}};
    for (const auto& [folder, value] : cases) {
        MediaResolver resolver;
        resolver.addSearchFolder(folder->path / "does-not-exist");  // skipped
        resolver.addSearchFolder(folder->path);
        const Result<ResolvedMedia> media = resolver.resolve(kAbstract3);
        ASSERT_TRUE(media.ok()) << media.error().text();
        EXPECT_FALSE(media->standIn);
        EXPECT_EQ(media->image.rgba[0], value);
    }
}

TEST(MediaResolver, FindsNonStockMediaByFileName) {
    TempFolder folder;
    writeSolidPng(folder.path / "my_texture.png", 3, 3, 44);
    MediaResolver resolver;
    resolver.addSearchFolder(folder.path);
    const Result<ResolvedMedia> media = resolver.resolve("/media/user/my_texture.png");
    ASSERT_TRUE(media.ok()) << media.error().text();
    EXPECT_EQ(media->image.rgba[0], 44);
}

TEST(MediaResolver, FallsBackToAStandInWithAOneLineNotice) {
    MediaResolver resolver;
    const Result<ResolvedMedia> media = resolver.resolve(kAbstract3);
    ASSERT_TRUE(media.ok()) << media.error().text();
    EXPECT_TRUE(media->standIn);
    EXPECT_EQ(media->image.width, 1024);
    EXPECT_EQ(media->image.height, 1024);
    EXPECT_EQ(media->image.rgba, makeStandIn(*findStockMedia(kAbstract3)).rgba);
    const std::string notice = formatDiagnostic(media->notice);
    EXPECT_EQ(media->notice.severity, Severity::Notice);
    EXPECT_EQ(media->notice.code, Code::MediaStandIn);
    EXPECT_EQ(notice.find('\n'), std::string::npos);
    for (const std::string& part :
         {std::string("'Abstract 3'"), kAbstract3, std::string("1024x1024"),
          std::string("stand-in"), std::string("--media-file")})
        EXPECT_NE(notice.find(part), std::string::npos) << part << " missing from: " << notice;
}

TEST(MediaResolver, UnknownIdIsAnErrorNamingIt) {
    MediaResolver resolver;
    const Result<ResolvedMedia> media = resolver.resolve("textures/not-anywhere.png");
    ASSERT_FALSE(media.ok());
    EXPECT_NE(media.error().text().find("textures/not-anywhere.png"), std::string::npos);
}

// Exports can name stock textures the table does not know: they get a 512x512 stand-in rather
// than failing the whole shader, with a warning (not a notice) that the size is a guess.
TEST(MediaResolver, UnknownStockPathGetsAFlaggedStandIn) {
    MediaResolver resolver;
    const Result<ResolvedMedia> media = resolver.resolve("/media/a/0123abcd.png");
    ASSERT_TRUE(media.ok()) << media.error().text();
    EXPECT_TRUE(media->standIn);
    EXPECT_EQ(media->image.width, 512);
    EXPECT_EQ(media->image.height, 512);
    EXPECT_NE(media->notice.message.find("/media/a/0123abcd.png"), std::string::npos);
    EXPECT_NE(media->notice.message.find("512x512 RGB, is a guess"), std::string::npos) << media->notice.message;
    EXPECT_EQ(media->notice.severity, Severity::Warning);
    const Result<ResolvedMedia> again = resolver.resolve("/media/a/0123abcd.png");
    EXPECT_EQ(again->image.rgba, media->image.rgba) << "deterministic";
}

// The image readers' fuzz findings (tests/fuzz/regressions/fuzz_image/): each file is refused with
// a reason, before the decoder that misbehaved on it sees it (an allocation of gigabytes from a few
// bytes, an endless loop, a slow path in a format Shadertoy never uses), or, for stb's JPEG
// findings (writes past its tables), by libjpeg-turbo, which decodes JPEGs now.
TEST(MediaImageFile, FuzzFindingsAreRefusedWithAReason) {
    const fs::path dir = fs::path(TOYHOST_SOURCE_DIR) / "tests/fuzz/regressions/fuzz_image";
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"stb-jpeg-dht-counts-over-256.jpg", "truncated"},
        {"stb-jpeg-progressive-ac-scan-uses-undefined-table.jpg", "Quantization table 0x02 was not defined"},
        {"stb-jpeg-scan-uses-undefined-huffman-table.jpg", "Bogus Huffman table definition"},
        {"stb-png-idat-length-alloc-over-1gib.png", "a PNG chunk is longer than the file"},
        {"stb-png-empty-idat-null-offset.png", "cannot decode image"},
        {"stb-hdr-rle-zero-count-endless-loop.hdr", "not a PNG or JPEG file"},
        {"stb-tga-declared-size-4350x33279-slow.tga", "not a PNG or JPEG file"},
        {"openexr-attribute-size-alloc-over-1gib.exr", "an attribute is larger than the file"},
        {"openexr-huge-data-window-alloc.exr", "not 1x1 .. 16384x16384"},
        {"openexr-box2i-declared-size-mismatch-alloc.exr", "an attribute's declared size does not match its type"},
    };
    for (const auto& [file, reason] : expected) {
        SCOPED_TRACE(file);
        const bool exr = fs::path(file).extension() == ".exr";
        const std::string message = exr ? (readExr(dir / file).ok() ? "<accepted>" : readExr(dir / file).error().text())
                                        : (loadImageFile(dir / file).ok() ? "<accepted>"
                                                                          : loadImageFile(dir / file).error().text());
        EXPECT_NE(message.find(reason), std::string::npos) << message;
    }
}
