// A fast deflate made for PNG image data: each band of rows gets one row filter (chosen by the
// estimated size of a sample of its rows) and one dynamic Huffman block built from that sample;
// the only matches are runs of a repeated pixel (distance 4), found without any hash search.
// Writes a complete zlib stream. CPU only, no GL needed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace toyhost {

class FastPngDeflate {
public:
    // Filter choice: one of the PNG filter types (image/PngFilters.h), or kChooseFilter: per band,
    // the type among Sub, Up and Paeth whose sample codes smallest.
    static constexpr int kChooseFilter = -1;

    // Writes the zlib stream of the filtered rows of an RGBA8 image (`rowsTopFirst[i]` is row i,
    // width * 4 bytes) into `out` from offset `at`, growing `out` when it is too small (never
    // shrinking it: the same buffer serves every frame without being cleared). Returns the offset
    // just past the stream.
    std::size_t compress(const std::uint8_t* const* rowsTopFirst, int width, int height, int filter,
                         std::vector<std::uint8_t>& out, std::size_t at);

private:
    std::vector<std::uint8_t> band_;    // one band's filtered lines (filter byte + row each)
    std::vector<std::uint8_t> sample_;  // one sampled line under a candidate filter
    std::vector<std::uint8_t> zeros_;   // the "row above" the first row
};

}  // namespace toyhost
