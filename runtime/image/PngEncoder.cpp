#include "image/PngEncoder.h"

#include <array>
#include <cstdlib>
#include <cstring>

#include <libdeflate.h>

#include "image/PngFilters.h"

namespace toyhost {
namespace {
constexpr std::size_t kBpp = 4;  // RGBA8

void put32(std::uint8_t* at, std::uint32_t v) {
    at[0] = static_cast<std::uint8_t>(v >> 24);
    at[1] = static_cast<std::uint8_t>(v >> 16);
    at[2] = static_cast<std::uint8_t>(v >> 8);
    at[3] = static_cast<std::uint8_t>(v);
}

// Completes the chunk whose `size` data bytes are already at at + 8: length, type and the CRC-32
// of type + data (PNG spec 5.3). Returns the offset just past the chunk.
std::size_t finishChunk(std::uint8_t* file, std::size_t at, const char type[4], std::size_t size) {
    put32(&file[at], static_cast<std::uint32_t>(size));
    std::memcpy(&file[at + 4], type, 4);
    put32(&file[at + 8 + size], libdeflate_crc32(0, &file[at + 4], 4 + size));
    return at + 12 + size;
}

// PNG filter type numbers of the fixed filters; -1 for the adaptive choice.
int filterType(PngFilter filter) {
    switch (filter) {
    case PngFilter::None: return kPngNone;
    case PngFilter::Sub: return kPngSub;
    case PngFilter::Up: return kPngUp;
    case PngFilter::Paeth: return kPngPaeth;
    case PngFilter::Adaptive: break;
    }
    return -1;
}
}  // namespace

PngSettings pngSettingsForLevel(int level) {
    // Index = --png-level. Chosen from measurements on rendered 1920x1080 frames (ocean, a flat
    // UI, noise, bench-trivial; docs/performance.md "PNG encoder"): the fast path (sampled filter,
    // runs only) costs about what storing the rows does, 3-10x less than libdeflate level 1, and is
    // 3-43x smaller than unfiltered libdeflate 1 on smooth or flat frames (13% larger than zlib 1
    // on a 3D render); libdeflate 1 with the per-row adaptive filter is smaller on all but noise;
    // the slower levels and filters buy the last percent.
    static constexpr std::array<PngSettings, 10> kLevels = {{
        {0, PngFilter::None},       // 0: stored, no compression
        {1, PngFilter::Adaptive, PngDeflate::FastRuns},  // 1: fastest compression (the capture default)
        {1, PngFilter::Adaptive},
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
    static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    constexpr std::size_t kIhdr = 8, kIdat = kIhdr + 25;
    const int fixed = filterType(settings.filter);
    auto ensure = [&](std::size_t size) {
        if (file_.size() < size) file_.resize(size);
    };
    ensure(kIdat + 8);

    std::size_t compressed = 0;
    if (settings.deflate == PngDeflate::FastRuns) {
        const int filter = fixed < 0 ? FastPngDeflate::kChooseFilter : fixed;
        compressed = fast_.compress(rowsTopFirst, width, height, filter, file_, kIdat + 8) - (kIdat + 8);
    } else {
        compressed = deflateWithLibdeflate(rowsTopFirst, width, height, settings, fixed);
        if (compressed == 0) return {};
    }
    ensure(kIdat + 8 + compressed + 4 + 12);

    std::uint8_t* file = file_.data();
    std::memcpy(file, kSignature, 8);
    std::uint8_t* ihdr = file + kIhdr + 8;
    put32(ihdr, static_cast<std::uint32_t>(width));
    put32(ihdr + 4, static_cast<std::uint32_t>(height));
    ihdr[8] = 8;   // bit depth
    ihdr[9] = 6;   // colour type: RGBA
    ihdr[10] = 0;  // deflate
    ihdr[11] = 0;  // adaptive filtering (filter method 0)
    ihdr[12] = 0;  // not interlaced
    finishChunk(file, kIhdr, "IHDR", 13);
    const std::size_t iend = finishChunk(file, kIdat, "IDAT", compressed);
    fileSize_ = finishChunk(file, iend, "IEND", 0);
    return {file_.data(), fileSize_};
}

std::size_t PngEncoder::deflateWithLibdeflate(const std::uint8_t* const* rowsTopFirst, int width, int height,
                                              PngSettings settings, int fixed) {
    if (!compressor_ || compressorLevel_ != settings.deflateLevel) {
        compressor_.reset(libdeflate_alloc_compressor(settings.deflateLevel));
        compressorLevel_ = compressor_ ? settings.deflateLevel : -1;
        if (!compressor_) return 0;
    }
    const std::size_t rowBytes = static_cast<std::size_t>(width) * kBpp;
    const std::size_t lineBytes = rowBytes + 1;
    const std::size_t rows = static_cast<std::size_t>(height);
    filtered_.resize(lineBytes * rows);

    std::vector<std::uint8_t> zeros;
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
            pngFilterRow(fixed, row, prior, line + 1, rowBytes);
            continue;
        }
        int best = 0;
        std::uint64_t bestSum = ~std::uint64_t(0);
        for (int type = 0; type < 5; ++type) {
            pngFilterRow(type, row, prior, trial[static_cast<std::size_t>(type)].data(), rowBytes);
            const std::uint64_t sum = pngSignedMagnitude(trial[static_cast<std::size_t>(type)].data(), rowBytes);
            if (sum < bestSum) {
                bestSum = sum;
                best = type;
            }
        }
        line[0] = static_cast<std::uint8_t>(best);
        std::memcpy(line + 1, trial[static_cast<std::size_t>(best)].data(), rowBytes);
    }

    // The zlib stream is compressed straight into the IDAT chunk's data field.
    constexpr std::size_t kData = 8 + 25 + 8;
    const std::size_t bound = libdeflate_zlib_compress_bound(compressor_.get(), filtered_.size());
    if (file_.size() < kData + bound) file_.resize(kData + bound);
    return libdeflate_zlib_compress(compressor_.get(), filtered_.data(), filtered_.size(), &file_[kData], bound);
}

}  // namespace toyhost
