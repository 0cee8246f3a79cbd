#include "image/PngEncoder.h"

#include <array>
#include <cstdlib>
#include <cstring>

#include <libdeflate.h>

namespace toyhost {
namespace {
constexpr std::size_t kBpp = 4;  // RGBA8: the filters' "corresponding byte of the pixel to the left"

void put32(std::uint8_t* at, std::uint32_t v) {
    at[0] = static_cast<std::uint8_t>(v >> 24);
    at[1] = static_cast<std::uint8_t>(v >> 16);
    at[2] = static_cast<std::uint8_t>(v >> 8);
    at[3] = static_cast<std::uint8_t>(v);
}

// Appends a chunk: length, type, data, CRC-32 of type + data (PNG spec 5.3).
void appendChunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, std::size_t size) {
    const std::size_t at = out.size();
    out.resize(at + 12 + size);
    put32(&out[at], static_cast<std::uint32_t>(size));
    std::memcpy(&out[at + 4], type, 4);
    if (size) std::memcpy(&out[at + 8], data, size);
    put32(&out[at + 8 + size], libdeflate_crc32(0, &out[at + 4], 4 + size));
}

std::uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return static_cast<std::uint8_t>(a);
    return static_cast<std::uint8_t>(pb <= pc ? b : c);
}

// Filter type `type` (0 none .. 4 paeth) of `row` into `out`; `prior` is the row above (zeros
// for the first row).
void filterRow(int type, const std::uint8_t* row, const std::uint8_t* prior, std::uint8_t* out, std::size_t n) {
    switch (type) {
    case 0: std::memcpy(out, row, n); return;
    case 1:
        for (std::size_t i = 0; i < kBpp; ++i) out[i] = row[i];
        for (std::size_t i = kBpp; i < n; ++i) out[i] = static_cast<std::uint8_t>(row[i] - row[i - kBpp]);
        return;
    case 2:
        for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>(row[i] - prior[i]);
        return;
    case 3:
        for (std::size_t i = 0; i < kBpp; ++i) out[i] = static_cast<std::uint8_t>(row[i] - (prior[i] >> 1));
        for (std::size_t i = kBpp; i < n; ++i)
            out[i] = static_cast<std::uint8_t>(row[i] - ((row[i - kBpp] + prior[i]) >> 1));
        return;
    default:
        for (std::size_t i = 0; i < kBpp; ++i) out[i] = static_cast<std::uint8_t>(row[i] - prior[i]);
        for (std::size_t i = kBpp; i < n; ++i)
            out[i] = static_cast<std::uint8_t>(row[i] - paeth(row[i - kBpp], prior[i], prior[i - kBpp]));
        return;
    }
}

std::uint64_t signedMagnitude(const std::uint8_t* bytes, std::size_t n) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += static_cast<std::uint64_t>(std::abs(static_cast<std::int8_t>(bytes[i])));
    return sum;
}

// PNG filter type numbers of the fixed filters.
int filterType(PngFilter filter) {
    switch (filter) {
    case PngFilter::None: return 0;
    case PngFilter::Sub: return 1;
    case PngFilter::Up: return 2;
    case PngFilter::Paeth: return 4;
    case PngFilter::Adaptive: break;
    }
    return -1;
}
}  // namespace

PngSettings pngSettingsForLevel(int level) {
    // Index = --png-level. Chosen from measurements on rendered 1920x1080 frames (ocean, a flat
    // UI, noise, bench-trivial; docs/performance.md "PNG encoder"): libdeflate level 1 on
    // unfiltered rows is the fastest compressor on every frame and smaller than zlib level 1
    // (what toyhost used before); the Up filter costs a little more and shrinks smooth or flat
    // frames 10-40x; the adaptive choice and libdeflate's slow levels buy the last percent.
    static constexpr std::array<PngSettings, 10> kLevels = {{
        {0, PngFilter::None},       // 0: stored, no compression
        {1, PngFilter::None},       // 1: fastest compression (the capture default)
        {1, PngFilter::Up},
        {4, PngFilter::Up},
        {4, PngFilter::Paeth},
        {6, PngFilter::Paeth},
        {6, PngFilter::Adaptive},   // 6: about libpng's default level in size
        {8, PngFilter::Adaptive},
        {10, PngFilter::Adaptive},
        {12, PngFilter::Adaptive},  // 9: smallest
    }};
    if (level < 0) level = 0;
    if (level > 9) level = 9;
    return kLevels[static_cast<std::size_t>(level)];
}

void PngEncoder::CompressorFree::operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }

PngEncoder::PngEncoder() = default;
PngEncoder::~PngEncoder() = default;
PngEncoder::PngEncoder(PngEncoder&&) noexcept = default;
PngEncoder& PngEncoder::operator=(PngEncoder&&) noexcept = default;

std::span<const std::uint8_t> PngEncoder::encode(const std::uint8_t* const* rowsTopFirst, int width, int height,
                                                 PngSettings settings) {
    if (!compressor_ || compressorLevel_ != settings.deflateLevel) {
        compressor_.reset(libdeflate_alloc_compressor(settings.deflateLevel));
        compressorLevel_ = compressor_ ? settings.deflateLevel : -1;
        if (!compressor_) return {};
    }
    const std::size_t rowBytes = static_cast<std::size_t>(width) * kBpp;
    const std::size_t lineBytes = rowBytes + 1;
    const std::size_t rows = static_cast<std::size_t>(height);
    filtered_.resize(lineBytes * rows);

    std::vector<std::uint8_t> zeros;
    const int fixed = filterType(settings.filter);
    std::array<std::vector<std::uint8_t>, 5> trial;
    if (fixed < 0)
        for (auto& t : trial) t.resize(rowBytes);
    for (std::size_t y = 0; y < rows; ++y) {
        const std::uint8_t* row = rowsTopFirst[y];
        const std::uint8_t* prior = y ? rowsTopFirst[y - 1] : nullptr;
        if (!prior) {
            zeros.assign(rowBytes, 0);
            prior = zeros.data();
        }
        std::uint8_t* line = &filtered_[y * lineBytes];
        if (fixed >= 0) {
            line[0] = static_cast<std::uint8_t>(fixed);
            filterRow(fixed, row, prior, line + 1, rowBytes);
            continue;
        }
        int best = 0;
        std::uint64_t bestSum = ~std::uint64_t(0);
        for (int type = 0; type < 5; ++type) {
            filterRow(type, row, prior, trial[type].data(), rowBytes);
            const std::uint64_t sum = signedMagnitude(trial[type].data(), rowBytes);
            if (sum < bestSum) {
                bestSum = sum;
                best = type;
            }
        }
        line[0] = static_cast<std::uint8_t>(best);
        std::memcpy(line + 1, trial[best].data(), rowBytes);
    }

    static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const std::size_t bound = libdeflate_zlib_compress_bound(compressor_.get(), filtered_.size());
    file_.clear();
    file_.reserve(8 + 25 + 12 + bound + 12);
    file_.insert(file_.end(), kSignature, kSignature + 8);
    std::uint8_t ihdr[13];
    put32(ihdr, static_cast<std::uint32_t>(width));
    put32(ihdr + 4, static_cast<std::uint32_t>(height));
    ihdr[8] = 8;   // bit depth
    ihdr[9] = 6;   // colour type: RGBA
    ihdr[10] = 0;  // deflate
    ihdr[11] = 0;  // adaptive filtering (filter method 0)
    ihdr[12] = 0;  // not interlaced
    appendChunk(file_, "IHDR", ihdr, sizeof ihdr);

    // The zlib stream is compressed straight into the IDAT chunk's data field.
    const std::size_t idat = file_.size();
    file_.resize(idat + 8 + bound);
    const std::size_t compressed = libdeflate_zlib_compress(compressor_.get(), filtered_.data(), filtered_.size(),
                                                            &file_[idat + 8], bound);
    if (compressed == 0) return {};  // cannot happen with the bound above
    put32(&file_[idat], static_cast<std::uint32_t>(compressed));
    std::memcpy(&file_[idat + 4], "IDAT", 4);
    file_.resize(idat + 8 + compressed);
    const std::uint32_t crc = libdeflate_crc32(0, &file_[idat + 4], 4 + compressed);
    file_.resize(file_.size() + 4);
    put32(&file_[idat + 8 + compressed], crc);
    appendChunk(file_, "IEND", nullptr, 0);
    return file_;
}

}  // namespace toyhost
