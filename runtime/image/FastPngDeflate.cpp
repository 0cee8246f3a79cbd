#include "image/FastPngDeflate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include <libdeflate.h>

#include "image/HuffmanCode.h"
#include "image/PngFilters.h"

namespace toyhost {
namespace {
constexpr std::size_t kBpp = 4;
constexpr int kLiteralLengthSymbols = 286;  // 0..255 bytes, 256 end of block, 257..285 lengths
constexpr int kEndOfBlock = 256;
constexpr int kDistanceSymbols = 4;  // codes 0..3; runs use code 3 (distance 4)
constexpr int kMaxLiteralBits = 13;  // shorter than deflate's 15 so four literals fit in 52 bits
constexpr std::size_t kBandBytes = std::size_t{1} << 20;  // filtered bytes per block, about
constexpr std::size_t kSampleStep = 16;                   // every 16th row of a band is sampled
constexpr std::size_t kMinRunPixels = 2;                  // shorter repeats are sent as literals

// Deflate's length codes (RFC 1951, 3.2.5): for each length 3..258 its symbol and extra bits.
struct LengthCode {
    std::uint16_t symbol;
    std::uint8_t extraBits;
    std::uint8_t extraValue;
};
struct LengthCodes {
    std::array<LengthCode, 259> of{};
    LengthCodes() {
        static constexpr std::uint16_t base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                                   31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
        static constexpr std::uint8_t extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                   2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
        for (int code = 0; code < 29; ++code) {
            const int last = code == 28 ? 258 : base[code + 1] - 1;
            for (int length = base[code]; length <= last && length <= 258; ++length)
                of[static_cast<std::size_t>(length)] = {static_cast<std::uint16_t>(257 + code), extra[code],
                                                        static_cast<std::uint8_t>(length - base[code])};
        }
        // 258 has its own code (285) though 227 + 31 would also reach it with code 284.
        of[258] = {285, 0, 0};
    }
};
const LengthCodes& lengthCodes() {
    static const LengthCodes codes;
    return codes;
}

// A run of `bytes` (a multiple of 4, >= 8) cut into deflate matches of 3..258 bytes.
template <class F>
void forEachMatch(std::size_t bytes, F&& match) {
    while (bytes) {
        std::size_t m = std::min<std::size_t>(bytes, 258);
        if (bytes > m && bytes - m < 3) m = bytes - 3;
        match(m);
        bytes -= m;
    }
}

std::uint32_t load32(const std::uint8_t* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}
std::uint64_t load64(const std::uint8_t* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}

// The one parse both passes share: a line (filter byte, then `pixels` RGBA pixels) as literals
// and runs of a pixel equal to the one before it. The filter byte and the first pixel are always
// literals, so no match reaches back across a line start (or into another block).
template <class Sink>
void parseLine(const std::uint8_t* line, std::size_t pixels, Sink& sink) {
    sink.literal(line[0]);
    const std::uint8_t* px = line + 1;
    if (pixels) sink.pixel(px);
    std::size_t p = 1;
    while (p < pixels) {
        const std::uint8_t* at = px + p * kBpp;
        if (load32(at) != load32(at - kBpp)) {
            sink.pixel(at);
            ++p;
            continue;
        }
        std::size_t q = p + 1;
        while (q + 1 < pixels && load64(px + q * kBpp) == load64(px + q * kBpp - kBpp)) q += 2;
        while (q < pixels && load32(px + q * kBpp) == load32(px + q * kBpp - kBpp)) ++q;
        if (q - p >= kMinRunPixels) {
            sink.run((q - p) * kBpp);
        } else {
            for (std::size_t i = p; i < q; ++i) sink.pixel(px + i * kBpp);
        }
        p = q;
    }
}

// Pass 1 (on sampled rows): symbol counts.
struct Histogram {
    std::array<std::uint32_t, kLiteralLengthSymbols> symbols{};
    std::uint32_t matches = 0;
    std::uint64_t extraBits = 0;
    void literal(std::uint8_t b) { ++symbols[b]; }
    void pixel(const std::uint8_t* p) {
        ++symbols[p[0]];
        ++symbols[p[1]];
        ++symbols[p[2]];
        ++symbols[p[3]];
    }
    void run(std::size_t bytes) {
        forEachMatch(bytes, [&](std::size_t m) {
            const LengthCode& c = lengthCodes().of[m];
            ++symbols[c.symbol];
            extraBits += c.extraBits;
            ++matches;
        });
    }
    // Estimated bits of this sample under its own optimal code (entropy + extra bits).
    double estimatedBits() const {
        double total = 0;
        for (std::uint32_t n : symbols) total += n;
        double bits = static_cast<double>(extraBits) + matches;  // + one bit of distance code each
        for (std::uint32_t n : symbols)
            if (n) bits += n * std::log2(total / n);
        return bits;
    }
};

// The LSB-first bit writer deflate wants, writing 8 bytes at a time (`out` keeps 8 bytes of slack).
struct BitWriter {
    std::uint8_t* out;
    std::size_t pos = 0;
    std::uint64_t bits = 0;
    unsigned count = 0;  // bits held, < 8 after flush()
    void put(std::uint64_t value, unsigned n) {  // count + n <= 64
        bits |= value << count;
        count += n;
    }
    void flush() {
        std::memcpy(out + pos, &bits, 8);
        pos += count >> 3;
        bits >>= count & 56;  // count < 64
        count &= 7;
    }
    void alignToByte() {
        count = (count + 7) & ~7u;
        flush();
    }
};

// Pass 2: the block's codes, and the sink that writes them.
struct BlockCodes {
    std::array<std::uint32_t, 256> literal{};  // reversed code | length << 16
    std::array<std::uint32_t, 259> match{};    // length code + extra bits + distance code | bits << 24
    std::uint32_t endOfBlock = 0;
};

struct Emitter {
    const BlockCodes& codes;
    BitWriter& w;
    void putCode(std::uint32_t c) { w.put(c & 0xffffu, c >> 16); }
    void literal(std::uint8_t b) {
        putCode(codes.literal[b]);
        w.flush();
    }
    void pixel(const std::uint8_t* p) {
        putCode(codes.literal[p[0]]);
        putCode(codes.literal[p[1]]);
        putCode(codes.literal[p[2]]);
        putCode(codes.literal[p[3]]);
        w.flush();
    }
    void run(std::size_t bytes) {
        forEachMatch(bytes, [&](std::size_t m) {
            const std::uint32_t c = codes.match[m];
            w.put(c & 0xffffffu, c >> 24);
            w.flush();
        });
    }
};

// Writes the dynamic block header (RFC 1951, 3.2.7) for these code lengths and fills `codes`.
void writeDynamicHeader(BitWriter& w, bool final, const std::array<std::uint8_t, kLiteralLengthSymbols>& litLengths,
                        const std::array<std::uint8_t, kDistanceSymbols>& distLengths, BlockCodes& codes) {
    std::array<std::uint16_t, kLiteralLengthSymbols> litCodes{};
    std::array<std::uint16_t, kDistanceSymbols> distCodes{};
    canonicalCodes(litLengths, litCodes);
    canonicalCodes(distLengths, distCodes);

    // The code lengths themselves are sent with the code-length alphabet (0..15 only: the run
    // symbols 16..18 would save a few dozen bytes a block).
    std::array<std::uint8_t, kLiteralLengthSymbols + kDistanceSymbols> all{};
    std::copy(litLengths.begin(), litLengths.end(), all.begin());
    std::copy(distLengths.begin(), distLengths.end(), all.begin() + kLiteralLengthSymbols);
    std::array<std::uint32_t, 19> clFreq{};
    for (std::uint8_t l : all) ++clFreq[l];
    int distinct = 0;
    for (std::uint32_t f : clFreq) distinct += f ? 1 : 0;
    if (distinct < 2) ++clFreq[clFreq[0] ? 1 : 0];  // inflate refuses an incomplete code-length code
    std::array<std::uint8_t, 19> clLengths{};
    std::array<std::uint16_t, 19> clCodes{};
    huffmanLengths(clFreq, 7, clLengths);
    canonicalCodes(clLengths, clCodes);
    static constexpr std::uint8_t kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    int clCount = 19;
    while (clCount > 4 && clLengths[kOrder[clCount - 1]] == 0) --clCount;

    w.put(final ? 1 : 0, 1);
    w.put(2, 2);  // dynamic Huffman
    w.put(kLiteralLengthSymbols - 257, 5);
    w.put(kDistanceSymbols - 1, 5);
    w.put(static_cast<std::uint64_t>(clCount - 4), 4);
    w.flush();
    for (int i = 0; i < clCount; ++i) {
        w.put(clLengths[kOrder[i]], 3);
        w.flush();
    }
    for (std::uint8_t l : all) {
        w.put(clCodes[l], clLengths[l]);
        w.flush();
    }

    for (std::size_t b = 0; b < 256; ++b) codes.literal[b] = litCodes[b] | std::uint32_t{litLengths[b]} << 16;
    codes.endOfBlock = litCodes[kEndOfBlock] | std::uint32_t{litLengths[kEndOfBlock]} << 16;
    const std::uint32_t dist = distCodes[3], distBits = distLengths[3];
    for (std::size_t m = 3; m <= 258; ++m) {
        const LengthCode& c = lengthCodes().of[m];
        std::uint32_t code = litCodes[c.symbol], bits = litLengths[c.symbol];
        code |= std::uint32_t{c.extraValue} << bits;
        bits += c.extraBits;
        code |= dist << bits;
        bits += distBits;
        codes.match[m] = code | bits << 24;
    }
}

// The band as stored blocks (when coding would make it larger): at most 65,535 bytes each.
void writeStored(BitWriter& w, bool final, const std::uint8_t* data, std::size_t size) {
    do {
        const std::size_t n = std::min<std::size_t>(size, 65535);
        w.put((final && n == size) ? 1 : 0, 1);
        w.put(0, 2);
        w.alignToByte();
        const std::uint8_t header[4] = {static_cast<std::uint8_t>(n), static_cast<std::uint8_t>(n >> 8),
                                        static_cast<std::uint8_t>(~n), static_cast<std::uint8_t>(~n >> 8)};
        std::memcpy(w.out + w.pos, header, 4);
        std::memcpy(w.out + w.pos + 4, data, n);
        w.pos += 4 + n;
        data += n;
        size -= n;
    } while (size);
}
}  // namespace

std::size_t FastPngDeflate::compress(const std::uint8_t* const* rowsTopFirst, int width, int height, int filter,
                                     std::vector<std::uint8_t>& out, std::size_t at) {
    const std::size_t pixels = static_cast<std::size_t>(width), rows = static_cast<std::size_t>(height);
    const std::size_t rowBytes = pixels * kBpp, lineBytes = rowBytes + 1;
    const std::size_t bandRows = std::min(rows, std::max<std::size_t>(1, kBandBytes / lineBytes));
    // Worst case per band: 13 bits a byte, the header, the stored form's block headers, slack.
    const std::size_t bandBytesMax = bandRows * lineBytes;
    const std::size_t bandBound = bandBytesMax * kMaxLiteralBits / 8 + 1024 + bandBytesMax / 65535 * 5;
    zeros_.assign(rowBytes, 0);
    sample_.resize(lineBytes);
    band_.resize(bandRows * lineBytes);

    auto reserve = [&](std::size_t pos, std::size_t more) {
        if (out.size() < pos + more) out.resize(pos + more);
    };
    reserve(at, 2 + bandBound + 16);
    BitWriter w{out.data() + at};
    w.put(0x78, 8);  // CMF: deflate, 32 KiB window
    w.put(0x01, 8);  // FLG: fastest, FCHECK so that CMF * 256 + FLG is a multiple of 31
    w.flush();

    std::uint32_t adler = 1;
    if (rows == 0) writeStored(w, true, nullptr, 0);
    for (std::size_t y0 = 0; y0 < rows; y0 += bandRows) {
        const std::size_t n = std::min(bandRows, rows - y0);
        const bool final = y0 + n == rows;
        auto prior = [&](std::size_t y) { return y ? rowsTopFirst[y - 1] : zeros_.data(); };

        // The band's filter and its code, both from a sample of its rows.
        Histogram chosen;
        int type = filter;
        if (type == kChooseFilter) {
            double best = 0;
            for (int candidate : {kPngSub, kPngUp, kPngPaeth}) {
                Histogram h;
                for (std::size_t y = y0; y < y0 + n; y += kSampleStep) {
                    sample_[0] = static_cast<std::uint8_t>(candidate);
                    pngFilterRow(candidate, rowsTopFirst[y], prior(y), sample_.data() + 1, rowBytes);
                    parseLine(sample_.data(), pixels, h);
                }
                const double bits = h.estimatedBits();
                if (type == kChooseFilter || bits < best) {
                    best = bits;
                    type = candidate;
                    chosen = h;
                }
            }
        } else {
            for (std::size_t y = y0; y < y0 + n; y += kSampleStep) {
                sample_[0] = static_cast<std::uint8_t>(type);
                pngFilterRow(type, rowsTopFirst[y], prior(y), sample_.data() + 1, rowBytes);
                parseLine(sample_.data(), pixels, chosen);
            }
        }

        std::uint8_t* band = band_.data();
        for (std::size_t i = 0; i < n; ++i) {
            std::uint8_t* line = band + i * lineBytes;
            line[0] = static_cast<std::uint8_t>(type);
            pngFilterRow(type, rowsTopFirst[y0 + i], prior(y0 + i), line + 1, rowBytes);
        }
        const std::size_t bandBytes = n * lineBytes;
        adler = libdeflate_adler32(adler, band, bandBytes);

        // Every symbol the band may use gets a code, seen in the sample or not.
        std::array<std::uint32_t, kLiteralLengthSymbols> freq = chosen.symbols;
        for (std::uint32_t& f : freq) ++f;
        std::array<std::uint8_t, kLiteralLengthSymbols> litLengths{};
        huffmanLengths(freq, kMaxLiteralBits, litLengths);
        const std::array<std::uint8_t, kDistanceSymbols> distLengths = {1, 0, 0, 1};  // code 0 unused, for completeness

        reserve(at + w.pos, bandBound + 16);
        w.out = out.data() + at;
        const BitWriter start = w;
        BlockCodes codes;
        writeDynamicHeader(w, final, litLengths, distLengths, codes);
        Emitter emit{codes, w};
        for (std::size_t i = 0; i < n; ++i) parseLine(band + i * lineBytes, pixels, emit);
        emit.putCode(codes.endOfBlock);
        w.flush();

        const std::size_t codedBits = (w.pos - start.pos) * 8 + w.count - start.count;
        const std::size_t storedBits = (bandBytes + (bandBytes / 65535 + 1) * 5) * 8 + 8;
        if (codedBits > storedBits) {
            w = start;
            writeStored(w, final, band, bandBytes);
        }
    }
    w.alignToByte();
    const std::uint8_t trailer[4] = {static_cast<std::uint8_t>(adler >> 24), static_cast<std::uint8_t>(adler >> 16),
                                     static_cast<std::uint8_t>(adler >> 8), static_cast<std::uint8_t>(adler)};
    reserve(at + w.pos, 4);
    std::memcpy(out.data() + at + w.pos, trailer, 4);
    return at + w.pos + 4;
}

}  // namespace toyhost
