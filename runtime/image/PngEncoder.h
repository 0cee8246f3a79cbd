// PngEncoder: 8-bit RGBA PNG files built in memory: every row filtered with one PNG filter (or
// the adaptive per-row choice), the filtered rows deflated by libdeflate into one zlib stream,
// wrapped in the standard container (signature, IHDR, IDAT, IEND). CPU only, no GL needed.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

struct libdeflate_compressor;

namespace toyhost {

// PNG row filters (PNG spec 9.2). Adaptive picks, per row, the filter whose bytes have the least
// sum of absolute values (read as signed), the heuristic the spec suggests and libpng uses.
enum class PngFilter { None, Sub, Up, Paeth, Adaptive };

struct PngSettings {
    int deflateLevel = 1;  // libdeflate's 0 (stored) .. 12 (smallest)
    PngFilter filter = PngFilter::Up;
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
    std::unique_ptr<libdeflate_compressor, CompressorFree> compressor_;
    int compressorLevel_ = -1;
    std::vector<std::uint8_t> filtered_;  // height * (1 + width * 4): filter byte + filtered row
    std::vector<std::uint8_t> file_;
};

}  // namespace toyhost
