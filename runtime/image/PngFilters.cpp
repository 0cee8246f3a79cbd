#include "image/PngFilters.h"

#include <cstring>

// GCC on x86-64: each hot loop is compiled twice, for AVX2 and for the baseline (SSE2), and the
// loader picks one by the CPU (an ifunc). Other compilers get the baseline only, and so does a
// ThreadSanitizer build: its instrumented ifunc resolver runs before TSan's runtime starts and
// crashes every program at load.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_THREAD__)
#define TOYHOST_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define TOYHOST_SIMD_CLONES
#endif

namespace toyhost {
namespace {
constexpr std::size_t kBpp = 4;  // RGBA8: the filters' "corresponding byte of the pixel to the left"

TOYHOST_SIMD_CLONES void subRow(const std::uint8_t* __restrict row, std::uint8_t* __restrict out, std::size_t n) {
    for (std::size_t i = 0; i < kBpp; ++i) out[i] = row[i];
    for (std::size_t i = kBpp; i < n; ++i) out[i] = static_cast<std::uint8_t>(row[i] - row[i - kBpp]);
}

TOYHOST_SIMD_CLONES void upRow(const std::uint8_t* __restrict row, const std::uint8_t* __restrict prior,
                               std::uint8_t* __restrict out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(row[i] - prior[i]);
}

TOYHOST_SIMD_CLONES void averageRow(const std::uint8_t* __restrict row, const std::uint8_t* __restrict prior,
                                    std::uint8_t* __restrict out, std::size_t n) {
    for (std::size_t i = 0; i < kBpp; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (prior[i] >> 1));
    for (std::size_t i = kBpp; i < n; ++i)
        out[i] = static_cast<std::uint8_t>(row[i] - ((row[i - kBpp] + prior[i]) >> 1));
}

// Paeth's predictor without branches: with p = a + b - c the three distances are |b - c|,
// |a - c| and |a + b - 2c|, and ties go to a, then b (the spec's order).
TOYHOST_SIMD_CLONES void paethRow(const std::uint8_t* __restrict row, const std::uint8_t* __restrict prior,
                                  std::uint8_t* __restrict out, std::size_t n) {
    for (std::size_t i = 0; i < kBpp; ++i) out[i] = static_cast<std::uint8_t>(row[i] - prior[i]);
    for (std::size_t i = kBpp; i < n; ++i) {
        const std::int16_t a = row[i - kBpp], b = prior[i], c = prior[i - kBpp];
        const std::int16_t ab = static_cast<std::int16_t>(b - c), ac = static_cast<std::int16_t>(a - c);
        const std::int16_t pa = static_cast<std::int16_t>(ab < 0 ? -ab : ab);
        const std::int16_t pb = static_cast<std::int16_t>(ac < 0 ? -ac : ac);
        const std::int16_t abc = static_cast<std::int16_t>(ab + ac);
        const std::int16_t pc = static_cast<std::int16_t>(abc < 0 ? -abc : abc);
        const std::int16_t predicted = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
        out[i] = static_cast<std::uint8_t>(row[i] - predicted);
    }
}

TOYHOST_SIMD_CLONES std::uint64_t signedMagnitude(const std::uint8_t* bytes, std::size_t n) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int8_t v = static_cast<std::int8_t>(bytes[i]);
        sum += static_cast<std::uint32_t>(v < 0 ? -v : v);
    }
    return sum;
}
}  // namespace

void pngFilterRow(int type, const std::uint8_t* row, const std::uint8_t* prior, std::uint8_t* out, std::size_t n) {
    switch (type) {
    case kPngNone: std::memcpy(out, row, n); return;
    case kPngSub: subRow(row, out, n); return;
    case kPngUp: upRow(row, prior, out, n); return;
    case kPngAverage: averageRow(row, prior, out, n); return;
    default: paethRow(row, prior, out, n); return;
    }
}

std::uint64_t pngSignedMagnitude(const std::uint8_t* bytes, std::size_t n) { return signedMagnitude(bytes, n); }

}  // namespace toyhost
