// The fast PNG path (FastPngDeflate, HuffmanCode) on adversarial images: every file it writes is
// decoded by libpng to exactly the pixels given (1x1, odd widths, widths that are no multiple of
// any vector width, all-same, noise, every byte value, runs cut at 258 and at row ends, many
// bands, a sample that misleads the code), and the Huffman codes are complete and length-limited.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include <png.h>

#include "LibpngDecode.h"
#include "TestPictures.h"

#include "image/HuffmanCode.h"
#include "image/PngEncoder.h"

using namespace toyhost;
using toyhost::testing::libpngDecode;

namespace {
using toyhost::testing::Picture;

template <class F>
Picture make(std::string name, int w, int h, F&& byte) {
    return toyhost::testing::makePicture(std::move(name), w, h, std::forward<F>(byte));
}

std::uint32_t lcg(std::uint32_t& state) {
    state = state * 1664525u + 1013904223u;
    return state >> 24;
}

// Encodes `p` with the fast path under every filter choice and checks libpng's decoding.
// Returns the largest file's size.
std::size_t expectRoundTrips(const Picture& p, PngEncoder& encoder) {
    std::vector<const std::uint8_t*> rows;
    for (int y = 0; y < p.height; ++y) rows.push_back(p.rgba.data() + static_cast<std::size_t>(y) * p.width * 4);
    std::size_t largest = 0;
    for (PngFilter filter : {PngFilter::Adaptive, PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth}) {
        const std::span<const std::uint8_t> file =
            encoder.encode(rows.data(), p.width, p.height, {1, filter, PngDeflate::FastRuns});
        largest = std::max(largest, file.size());
        int w = 0, h = 0;
        const std::vector<std::uint8_t> decoded = libpngDecode(file, w, h);
        EXPECT_EQ(w, p.width) << p.name;
        EXPECT_EQ(h, p.height) << p.name;
        EXPECT_TRUE(decoded == p.rgba) << p.name << " (" << p.width << "x" << p.height << ") filter "
                                       << static_cast<int>(filter);
    }
    return largest;
}
}  // namespace

TEST(FastPngDeflate, OneByOneAndOneRowAndOneColumnRoundTrip) {
    PngEncoder encoder;
    expectRoundTrips(make("1x1", 1, 1, [](int, int, int c) { return 17 * c; }), encoder);
    expectRoundTrips(make("2x1", 2, 1, [](int x, int, int c) { return x + c; }), encoder);
    expectRoundTrips(make("1x9", 1, 9, [](int, int y, int c) { return y * 40 + c; }), encoder);
    expectRoundTrips(make("row of one colour", 700, 1, [](int, int, int c) { return 9 + c; }), encoder);
}

TEST(FastPngDeflate, EveryWidthUpToThreeVectorsRoundTrips) {
    // Widths 1..49 pixels: every remainder of the SIMD filter loops (16 and 32 bytes) and of the
    // two-pixel run scan; half the rows flat (runs), half varying (literals).
    PngEncoder encoder;
    for (int w = 1; w <= 49; ++w)
        expectRoundTrips(make("width " + std::to_string(w), w, 7,
                              [](int x, int y, int c) { return y % 2 ? 100 + c : (x * 37 + y * 11 + c * 5) & 255; }),
                         encoder);
}

TEST(FastPngDeflate, AllSamePixelsCompressToAlmostNothing) {
    PngEncoder encoder;
    const Picture p = make("all same", 1000, 300, [](int, int, int c) { return 200 - c; });
    const std::size_t size = expectRoundTrips(p, encoder);
    EXPECT_LT(size, p.rgba.size() / 100);
}

TEST(FastPngDeflate, NoiseStaysNearItsRawSize) {
    // Incompressible: the stored form caps the growth (a block is stored when coding is larger).
    PngEncoder encoder;
    std::uint32_t state = 99;
    const Picture p = make("noise", 333, 211, [&](int, int, int) { return lcg(state); });
    const std::size_t size = expectRoundTrips(p, encoder);
    EXPECT_LT(size, p.rgba.size() + p.rgba.size() / 50);
}

TEST(FastPngDeflate, EveryByteValueInEveryChannelRoundTrips) {
    PngEncoder encoder;
    expectRoundTrips(make("every byte", 256, 5, [](int x, int y, int c) { return (x + y * 3 + c * 64) & 255; }),
                     encoder);
    expectRoundTrips(make("every pair", 256, 256, [](int x, int y, int c) { return c % 2 ? x : y; }), encoder);
}

TEST(FastPngDeflate, RunsOfEveryLengthAcrossMatchLimitsAndRowEnds) {
    // Runs of 1..300 pixels of one colour between single different pixels: matches of 8 bytes up
    // to 1,200 cut at deflate's 258 (with remainders 1 and 2 that must not be sent alone).
    PngEncoder encoder;
    std::vector<int> colourOf;
    for (int run = 1, colour = 0; colourOf.size() < 45000; ++run, ++colour) {
        colourOf.insert(colourOf.end(), static_cast<std::size_t>(run % 301), colour);
        colourOf.push_back(colour + 1000);
    }
    expectRoundTrips(make("runs", 301, 149,
                          [&](int x, int y, int c) {
                              const int v = colourOf[static_cast<std::size_t>(y * 301 + x)];
                              return (v * (c + 1) * 7) & 255;
                          }),
                     encoder);
}

TEST(FastPngDeflate, ManyBandsWithDifferentContentRoundTrip) {
    // About 4.5 MB: several ~1 MB bands, each choosing its own filter and code; the content
    // changes from gradient to flat to noise to stripes between and inside bands.
    PngEncoder encoder;
    std::uint32_t state = 5;
    expectRoundTrips(make("bands", 1111, 1013,
                          [&](int x, int y, int c) {
                              switch ((y / 190) % 4) {
                              case 0: return (x + 2 * y + c * 30) & 255;
                              case 1: return 77 + c;
                              case 2: return static_cast<int>(lcg(state));
                              default: return (x / 3 % 2) * 255 - c;
                              }
                          }),
                     encoder);
}

TEST(FastPngDeflate, ASampleThatMisleadsTheCodeStillRoundTripsAndIsCapped) {
    // Only every 16th row is sampled: make exactly those rows flat and all others noise. The
    // code then fits zeros, the noise codes badly, and the band is stored instead.
    PngEncoder encoder;
    std::uint32_t state = 7;
    const Picture p = make("misleading sample", 512, 400,
                           [&](int, int y, int) { return y % 16 == 0 ? 0 : static_cast<int>(lcg(state)); });
    const std::size_t size = expectRoundTrips(p, encoder);
    EXPECT_LT(size, p.rgba.size() + p.rgba.size() / 50);
}

TEST(FastPngDeflate, PngLevelOneIsTheFastPathAndTheOthersLibdeflate) {
    EXPECT_EQ(pngSettingsForLevel(1).deflate, PngDeflate::FastRuns);
    EXPECT_EQ(pngSettingsForLevel(0).deflate, PngDeflate::Libdeflate);
    for (int level = 2; level <= 9; ++level) EXPECT_EQ(pngSettingsForLevel(level).deflate, PngDeflate::Libdeflate);
}

namespace {
// Kraft sum of the used lengths, as a multiple of 2^-15: exactly 1 << 15 for a complete code.
std::uint64_t kraft(const std::vector<std::uint8_t>& lengths) {
    std::uint64_t sum = 0;
    for (std::uint8_t l : lengths)
        if (l) sum += std::uint64_t{1} << (15 - l);
    return sum;
}
}  // namespace

TEST(HuffmanCode, LengthsAreCompleteAndWithinTheLimitEvenForSkewedCounts) {
    // Fibonacci counts make the deepest unlimited tree; limits 7, 13 and 15 must still hold.
    std::vector<std::uint32_t> freq(286);
    std::uint32_t a = 1, b = 1;
    for (std::size_t i = 0; i < 40; ++i) {
        freq[i] = a;
        const std::uint32_t next = a + b;
        a = b;
        b = next > 1000000000u ? 1000000000u : next;
    }
    for (std::size_t i = 40; i < freq.size(); ++i) freq[i] = 1;
    for (int limit : {9, 13, 15}) {
        std::vector<std::uint8_t> lengths(freq.size());
        huffmanLengths(freq, limit, lengths);
        EXPECT_EQ(kraft(lengths), std::uint64_t{1} << 15) << "limit " << limit;
        for (std::uint8_t l : lengths) {
            EXPECT_GE(l, 1);
            EXPECT_LE(l, limit);
        }
    }
}

TEST(HuffmanCode, UnusedSymbolsGetNoCodeAndTwoSymbolsOneBitEach) {
    std::vector<std::uint32_t> freq = {0, 5, 0, 0, 1000, 0};
    std::vector<std::uint8_t> lengths(freq.size());
    huffmanLengths(freq, 15, lengths);
    EXPECT_EQ(lengths, (std::vector<std::uint8_t>{0, 1, 0, 0, 1, 0}));
    std::vector<std::uint16_t> codes(freq.size());
    canonicalCodes(lengths, codes);
    EXPECT_EQ(codes[1], 0);
    EXPECT_EQ(codes[4], 1);
}

TEST(HuffmanCode, CanonicalCodesFollowRfc1951sExample) {
    // RFC 1951 3.2.2: lengths (3,3,3,3,3,2,4,4) give F=00, A=010 .. E=110, G=1110, H=1111; the
    // codes here are bit-reversed for an LSB-first writer.
    const std::vector<std::uint8_t> lengths = {3, 3, 3, 3, 3, 2, 4, 4};
    std::vector<std::uint16_t> codes(lengths.size());
    canonicalCodes(lengths, codes);
    const std::vector<std::uint16_t> msbFirst = {0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111};
    for (std::size_t s = 0; s < lengths.size(); ++s) {
        std::uint16_t reversed = 0;
        for (int b = 0; b < lengths[s]; ++b)
            reversed = static_cast<std::uint16_t>(reversed << 1 | ((codes[s] >> b) & 1));
        EXPECT_EQ(reversed, msbFirst[s]) << "symbol " << s;
    }
}
