// ImageWriters: PNG (8-bit RGBA) and OpenEXR (32-bit float RGBA) files from read-back pixels, and
// readers for the same formats for tests and tools. Files are written atomically: complete or
// absent. CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

#include "core/Result.h"
#include "media/Image.h"

namespace toyhost {

// `rgbaBottomUp` holds width * height * 4 bytes, bottom row first as glReadPixels returns them;
// the file gets the top row first. `compressionLevel` is zlib's 0 (none) .. 9 (smallest); the
// default 1 favours speed when capturing frames. Levels 0-2 write rows unfiltered, 3-9 use
// libpng's adaptive filters (smaller, about twice the time).
Status writePng(const std::filesystem::path& path, int width, int height,
                std::span<const std::uint8_t> rgbaBottomUp, int compressionLevel = 1);

// `rgbaBottomUp` holds width * height * 4 floats, bottom row first. Writes 32-bit FLOAT channels
// A, B, G, R (EXR keeps channels sorted by name), uncompressed, scanlines in increasing y with the
// image's top row as scanline 0. That is the layout of Shadertoy's own "export buffer to EXR"
// (piLibs piExportToEXR, called by effect.js saveScreenshot): FLOAT B/G/R, no compression,
// INCREASING_Y, GL rows flipped so the top comes first. The site drops alpha (3 channels); we keep
// it, and readers that ignore A see the same RGB.
Status writeExr(const std::filesystem::path& path, int width, int height,
                std::span<const float> rgbaBottomUp);

// Reads any scanline or tiled EXR into RGBA float, rows bottom first (the inverse of writeExr).
// Missing channels read as R=G=B=0, A=1 (so a site export without alpha has A=1).
Result<ImageF32> readExr(const std::filesystem::path& path);

// Reads a PNG (or anything loadImageFile reads) to RGBA8, rows top first.
Result<Image8> readPng(const std::filesystem::path& path);

}  // namespace toyhost
