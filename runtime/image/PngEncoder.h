// PngEncoder: 8-bit RGBA PNG files built in memory: every row filtered with one PNG filter (or
// the adaptive per-row choice), the filtered rows deflated into one zlib stream by libdeflate or
// by toyhost's run-only fast path (image/FastPngDeflate.h), wrapped in the standard container
// (signature, IHDR, IDAT, IEND). CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "image/FastPngDeflate.h"

struct libdeflate_compressor;

namespace toyhost {

// PNG row filters (PNG spec 9.2). Adaptive, with libdeflate, picks per row the filter whose bytes
// have the least sum of absolute values (read as signed), the heuristic the spec suggests and
// libpng uses; with the fast path it picks per band of rows (about 1 MB) among Sub, Up and Paeth
// the one whose sampled rows code smallest.
enum class PngFilter { None, Sub, Up, Paeth, Adaptive };

enum class PngDeflate {
    Libdeflate,  // libdeflate at deflateLevel: LZ77 with a hash search
    FastRuns,    // FastPngDeflate: Huffman codes from a sample, runs of a repeated pixel, no search
};

struct PngSettings {
    int deflateLevel = 1;  // libdeflate's 0 (stored) .. 12 (smallest); unused by FastRuns
    PngFilter filter = PngFilter::Up;
    PngDeflate deflate = PngDeflate::Libdeflate;
};

// What `--png-level` 0..9 means (fastest .. smallest; docs/performance.md "PNG encoder" has the
// measurements the choice rests on).
PngSettings pngSettingsForLevel(int level);

class PngEncoder {
public:
    PngEncoder();
    ~PngEncoder();
    PngEncoder(PngEncoder&&) noexcept;
    PngEncoder& operator=(PngEncoder&&) noexcept;

    // `rowsTopFirst[i]` points at row i of the image as the file stores it (top first), each
    // width * 4 bytes. Returns the whole file; it stays valid until the next encode(). Empty
    // only when memory for the compressor cannot be had.
    std::span<const std::uint8_t> encode(const std::uint8_t* const* rowsTopFirst, int width, int height,
                                         PngSettings settings);

private:
    struct CompressorFree {
        void operator()(libdeflate_compressor* c) const;
    };
    // The zlib stream into file_ from the IDAT data offset; its size, 0 when out of memory.
    std::size_t deflateWithLibdeflate(const std::uint8_t* const* rowsTopFirst, int width, int height,
                                      PngSettings settings, int fixedFilter);

    std::unique_ptr<libdeflate_compressor, CompressorFree> compressor_;
    int compressorLevel_ = -1;
    FastPngDeflate fast_;
    std::vector<std::uint8_t> filtered_;  // height * (1 + width * 4): filter byte + filtered row
    // The file is file_[0, fileSize_). file_ only grows, so that a frame does not pay for
    // clearing the compressor's worst-case room again.
    std::vector<std::uint8_t> file_;
    std::size_t fileSize_ = 0;
};

}  // namespace toyhost
