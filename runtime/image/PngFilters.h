// The PNG row filters (PNG spec 9.2) on 8-bit RGBA rows, written as loops the compiler turns
// into SIMD code (AVX2 chosen at run time where the CPU has it), and the cost heuristic the
// adaptive choice uses. CPU only, no GL needed.
#pragma once

#include <cstddef>
#include <cstdint>

namespace toyhost {

// PNG filter type numbers (the byte that starts each filtered row).
enum PngFilterType : int { kPngNone = 0, kPngSub = 1, kPngUp = 2, kPngAverage = 3, kPngPaeth = 4 };

// Filters `n` bytes of `row` (RGBA8, n a multiple of 4) with filter `type` into `out`; `prior` is
// the unfiltered row above (all zeros for the first row, as the spec says).
void pngFilterRow(int type, const std::uint8_t* row, const std::uint8_t* prior, std::uint8_t* out, std::size_t n);

// Sum of the bytes' absolute values read as signed: the spec's heuristic for the adaptive choice.
std::uint64_t pngSignedMagnitude(const std::uint8_t* bytes, std::size_t n);

}  // namespace toyhost
