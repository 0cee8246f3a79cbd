// BandedImageWriter: one PNG or EXR image written a band of rows at a time, top band first, so an
// image far larger than memory (a tiled still of 32768x18432) never has to be held whole. The
// file is written under a temporary name beside its own and renamed into place by finish(), so it
// is complete or absent (core/AtomicFile.h's rule). PNG through libpng, row by row (zlib level from
// --png-level); EXR as 32-bit float (or half) scanlines in increasing y, as writeExr writes them.
// CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

#include "core/Result.h"
#include "image/ImageWriters.h"

namespace toyhost {

class BandedImageWriter {
public:
    enum class Format { Png, Exr };
    // Opens the temporary file. `pngLevel` 0..9 (zlib level), `exr` as for writeExr.
    static Result<std::unique_ptr<BandedImageWriter>> open(const std::filesystem::path& path, int width, int height,
                                                           Format format, int pngLevel = 1, ExrSettings exr = {});
    ~BandedImageWriter();  // without finish(): the temporary file is removed
    BandedImageWriter(const BandedImageWriter&) = delete;
    BandedImageWriter& operator=(const BandedImageWriter&) = delete;

    // The next `rows` rows (top first), width * 4 values each: bytes for PNG, floats for EXR.
    Status writeRows(std::span<const std::uint8_t> rgba, int rows);
    Status writeRows(std::span<const float> rgba, int rows);
    // After the last row: completes the file and renames it into place.
    Status finish();

    struct Impl;

private:
    explicit BandedImageWriter(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace toyhost
