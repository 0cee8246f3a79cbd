// ImageWriters: PNG (8-bit RGBA) and OpenEXR (32-bit float RGBA) files from pixels held rows
// bottom first (image/Image.h), and readers of the same formats for tests and tools. Files are
// written atomically: complete or absent. CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <span>
#include <vector>

#include "core/AtomicFile.h"
#include "core/Result.h"
#include "image/Image.h"
#include "image/PngEncoder.h"

namespace toyhost {

// Working memory a writer reuses from one file to the next, so that writing frames allocates no
// pixel-sized buffer once the first one is written (the codec libraries keep their own state).
struct ImageScratch {
    std::vector<const std::uint8_t*> rows;  // PNG row table
    PngEncoder png;                         // its compressor and filtered rows
    // Of the last file written: seconds spent building its bytes and writing them out (an EXR is
    // encoded while it is written by OpenEXR: all of it counts as encoding).
    double encodeSeconds = 0;
    double writeSeconds = 0;
    std::vector<float> floats;              // EXR rows in file order
    std::vector<std::uint16_t> halves;      // the same as half floats (--exr-half)
};

// `rgba` holds width * height * 4 bytes, rows bottom first; the file gets the top row first.
// `compressionLevel` is `--png-level`: 0 (stored) .. 9 (smallest), mapped to a row filter and a
// deflate (the fast path or a libdeflate level) by pngSettingsForLevel (image/PngEncoder.h); the
// default 1 favours speed when capturing frames.
// `parents`: whether missing folders above `path` are created (core/AtomicFile.h).
Status writePng(const std::filesystem::path& path, int width, int height, std::span<const std::uint8_t> rgba,
                int compressionLevel = 1, ImageScratch* scratch = nullptr,
                ParentFolders parents = ParentFolders::Create);

// How an EXR is stored (`--exr-compression`, `--exr-half`). The default (no compression, 32-bit
// float) is the site's own buffer export; none, rle, zips, zip and piz are lossless; pxr24 rounds
// 32-bit floats to 24 bits; b44, b44a, dwaa and dwab are lossy (b44/b44a only on half channels,
// 32-bit ones are stored as they are).
enum class ExrCompression { None, Rle, Zips, Zip, Piz, Pxr24, B44, B44a, Dwaa, Dwab };
struct ExrSettings {
    ExrCompression compression = ExrCompression::None;
    bool half = false;  // 16-bit half channels instead of 32-bit float
};
// The name `--exr-compression` takes ("zip"), and the reverse (std::nullopt: unknown).
std::string_view exrCompressionName(ExrCompression compression);
std::optional<ExrCompression> exrCompressionNamed(std::string_view name);
// "none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab"
std::string exrCompressionNames();
// OpenEXR's Imf::Compression value for `compression` (as an int: this header does not include
// OpenEXR's).
int exrCompressionCode(ExrCompression compression);

// `rgba` holds width * height * 4 floats, rows bottom first. Writes 32-bit FLOAT channels
// A, B, G, R (EXR keeps channels sorted by name), uncompressed, scanlines in increasing y with the
// image's top row as scanline 0. That is the layout of Shadertoy's own "export buffer to EXR"
// (piLibs piExportToEXR, called by effect.js saveScreenshot): FLOAT B/G/R, no compression,
// INCREASING_Y, GL rows flipped so the top comes first. The site drops alpha (3 channels); we keep
// it, and readers that ignore A see the same RGB.
// With `settings` other than the default: those compression and channel types instead.
Status writeExr(const std::filesystem::path& path, int width, int height, std::span<const float> rgba,
                ImageScratch* scratch = nullptr, ExrSettings settings = {},
                ParentFolders parents = ParentFolders::Create);

// Reads any scanline or tiled EXR into RGBA float, rows bottom first (the inverse of writeExr).
// Missing channels read as R=G=B=0, A=1 (so a site export without alpha has A=1).
Result<ImageF32> readExr(const std::filesystem::path& path);

// Reads a PNG (or anything loadImageFile reads) to RGBA8, rows bottom first.
Result<Image8> readPng(const std::filesystem::path& path);

}  // namespace toyhost
