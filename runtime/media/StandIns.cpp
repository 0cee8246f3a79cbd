#include "media/StandIns.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "media/FontAtlas.h"

namespace toyhost {

// ---- Stand-ins ---------------------------------------------------------------------------------
// Everything below but the font (drawn by FreeType from DejaVu, media/FontAtlas.h: the same bytes for
// the same FreeType and font files) uses integer arithmetic only, so the bytes are identical on every compiler and
// CPU. The generators write RGBA; conformToChannels then applies the file's channel count.
namespace {
using Bytes = std::vector<std::uint8_t>;

std::uint64_t mix64(std::uint64_t z) {  // the splitmix64 finaliser
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// splitmix64 stream handing out bytes, low byte of each 64-bit word first.
class ByteStream {
public:
    explicit ByteStream(std::uint64_t seed) : state_(seed) {}
    std::uint8_t next() {
        if (left_ == 0) {
            word_ = mix64(state_ += 0x9e3779b97f4a7c15ULL);
            left_ = 8;
        }
        const auto byte = static_cast<std::uint8_t>(word_);
        word_ >>= 8;
        --left_;
        return byte;
    }

private:
    std::uint64_t state_, word_ = 0;
    int left_ = 0;
};

std::uint64_t seedFrom(std::string_view text, std::uint64_t salt = 0) {
    std::uint64_t h = 0xcbf29ce484222325ULL;  // FNV-1a 64
    for (char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    return mix64(h ^ salt);
}

Image8 blank(const StockMediaInfo& info) {
    Image8 image{info.width, info.height, {}};
    image.rgba.assign(
        static_cast<std::size_t>(info.width) * static_cast<std::size_t>(info.height) * 4, 0);
    return image;
}

std::size_t pixelIndex(int width, int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
}

void putPixel(Image8& image, int x, int y, int r, int g, int b, int a) {
    std::uint8_t* p = &image.rgba[pixelIndex(image.width, x, y) * 4];
    p[0] = static_cast<std::uint8_t>(r);
    p[1] = static_cast<std::uint8_t>(g);
    p[2] = static_cast<std::uint8_t>(b);
    p[3] = static_cast<std::uint8_t>(a);
}

// Grey files show R=G=B (from R); files without alpha show A=255, as the upload would.
void conformToChannels(Image8& image, int channels) {
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        if (channels <= 2) image.rgba[i + 1] = image.rgba[i + 2] = image.rgba[i];
        if (channels == 1 || channels == 3) image.rgba[i + 3] = 255;
    }
}

Image8 whiteNoise(const StockMediaInfo& info) {
    Image8 image = blank(info);
    ByteStream random(seedFrom(info.hash));
    for (std::size_t i = 0; i < image.rgba.size(); i += 4)
        for (int c = 0; c < (info.channels == 1 ? 1 : 4); ++c) image.rgba[i + c] = random.next();
    return image;
}

// One axis of a lattice with `cells` cells over `size` pixels: for each pixel the two lattice
// indices it lies between (wrapping, so the texture tiles) and the smoothstep weight in 1/65536.
struct LatticeAxis {
    std::vector<std::size_t> lower, upper;
    std::vector<std::int64_t> weight;
    LatticeAxis(int size, int cells) {
        for (int p = 0; p < size; ++p) {
            const int cell = p * cells / size;
            const std::int64_t t = static_cast<std::int64_t>(p * cells % size) * 65536 / size;
            lower.push_back(static_cast<std::size_t>(cell));
            upper.push_back(static_cast<std::size_t>((cell + 1) % cells));
            weight.push_back((t * t * (3 * 65536 - 2 * t)) >> 32);
        }
    }
};

// Tileable value noise summed over octaves from 4 cells across down to 2-pixel cells, so every mip
// level keeps some detail. Fixed point throughout; the result is 0..255.
Bytes valueNoise(int width, int height, std::uint64_t seed) {
    const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
    std::vector<std::int64_t> sum(w * h, 0);
    std::int64_t amplitude = 1024, amplitudeSum = 0;
    const int longest = std::max(width, height);
    for (int cells = 4; cells * 2 <= longest; cells *= 2, amplitude = amplitude * 5 / 8) {
        const int cellsX = std::max(1, cells * width / longest),
                  cellsY = std::max(1, cells * height / longest);
        Bytes lattice(static_cast<std::size_t>(cellsX) * static_cast<std::size_t>(cellsY));
        ByteStream random(mix64(seed ^ static_cast<std::uint64_t>(cells)));
        for (auto& v : lattice) v = random.next();
        const LatticeAxis ax(width, cellsX), ay(height, cellsY);
        for (std::size_t y = 0; y < h; ++y) {
            const std::uint8_t* row0 = &lattice[ay.lower[y] * static_cast<std::size_t>(cellsX)];
            const std::uint8_t* row1 = &lattice[ay.upper[y] * static_cast<std::size_t>(cellsX)];
            for (std::size_t x = 0; x < w; ++x) {
                const std::int64_t a = row0[ax.lower[x]], b = row0[ax.upper[x]];
                const std::int64_t c = row1[ax.lower[x]], d = row1[ax.upper[x]];
                const std::int64_t top = a * 65536 + (b - a) * ax.weight[x];
                const std::int64_t bottom = c * 65536 + (d - c) * ax.weight[x];
                const std::int64_t v =
                    (top * 65536 + (bottom - top) * ay.weight[y]) >> 32;  // 0..255
                sum[y * w + x] += v * amplitude;
            }
        }
        amplitudeSum += amplitude;
    }
    Bytes out(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        // Stretch the contrast: sums of octaves cluster around the middle.
        const std::int64_t v = 128 + (sum[i] / std::max<std::int64_t>(amplitudeSum, 1) - 128) * 2;
        out[i] = static_cast<std::uint8_t>(std::clamp<std::int64_t>(v, 0, 255));
    }
    return out;
}

int lerp8(int a, int b, int t) { return a + (b - a) * t / 255; }

Image8 photo(const StockMediaInfo& info) {
    Image8 image = blank(info);
    const Bytes shade = valueNoise(info.width, info.height, seedFrom(info.hash, 1));
    const Bytes tint = valueNoise(info.width, info.height, seedFrom(info.hash, 2));
    ByteStream random(seedFrom(info.hash, 3));
    std::array<int, 9> ramp{};  // dark, mid, light colours drawn per texture
    for (int i = 0; i < 9; ++i) ramp[i] = (i / 3) * 80 + random.next() % 96;
    for (int y = 0; y < info.height; ++y)
        for (int x = 0; x < info.width; ++x) {
            const std::size_t i = pixelIndex(info.width, x, y);
            const int v = shade[i], lo = v < 128 ? 0 : 3, t = v < 128 ? v * 2 : (v - 128) * 2;
            // Photos have hard object boundaries, not just smooth shading: contour bands of the
            // tint noise alternate bright and dark, so edge detectors and thresholds find edges.
            const int band = tint[i] * 6 / 256, edge = band % 2 ? 24 : 255;
            std::array<int, 3> rgb{};
            for (int c = 0; c < 3; ++c)
                rgb[c] = lerp8(ramp[lo + c], ramp[lo + 3 + c], std::min(t, 255)) *
                         (160 + tint[i] * 95 / 255) / 255 * edge / 255;
            if (info.channels == 1) rgb[0] = v * edge / 255;
            putPixel(image, x, y, rgb[0], rgb[1], rgb[2], 255);
        }
    return image;
}

// The 8x8 ordered-dither (Bayer) matrix, built from the 2x2 one: low coordinate bits give the
// high value bits. How the real file scales the 0..63 index is not known; it is spread to 0..255.
Image8 bayer(const StockMediaInfo& info) {
    Image8 image = blank(info);
    for (int y = 0; y < info.height; ++y)
        for (int x = 0; x < info.width; ++x) {
            int v = 0;
            for (int k = 0; k < 3; ++k) {
                const int xk = (x >> k) & 1, yk = (y >> k) & 1;
                v |= ((xk ^ yk) << (2 * (2 - k) + 1)) | (yk << (2 * (2 - k)));
            }
            const int byte = (v * 255 + 31) / 63;
            putPixel(image, x, y, byte, byte, byte, 255);
        }
    return image;
}

// 16x16 glyph cells: RGB is the glyph mask, A a distance field (128 on the edge, higher inside).
Image8 glyphAtlas(const StockMediaInfo& info) {
    Image8 image = blank(info);
    const int cellW = info.width / 16, cellH = info.height / 16;
    for (int y = 0; y < info.height; ++y)
        for (int x = 0; x < info.width; ++x) {
            const int code = (y / cellH) * 16 + x / cellW;
            if (code < 32) continue;  // control characters stay empty
            const std::uint64_t h = mix64(static_cast<std::uint64_t>(code));
            const int halfW =
                cellW / 8 + static_cast<int>(h % static_cast<std::uint64_t>(cellW / 4));
            const int halfH =
                cellH / 8 + static_cast<int>((h >> 16) % static_cast<std::uint64_t>(cellH / 4));
            const int dx = std::abs(x % cellW - cellW / 2), dy = std::abs(y % cellH - cellH / 2);
            const int distance = std::max(dx - halfW, dy - halfH);  // < 0 inside the glyph box
            const int mask = distance < 0 ? 255 : 0;
            putPixel(image, x, y, mask, mask, mask, std::clamp(128 - distance * 8, 0, 255));
        }
    return image;
}

// The site's font texture's layout with DejaVu's glyphs (media/FontAtlas.h), so text reads as text;
// boxes in the same grid where the font is not installed (or FreeType fails).
Image8 fontStandIn(const StockMediaInfo& info) {
    if (std::optional<std::filesystem::path> font = atlasFontFile())
        if (Result<Image8> atlas = fontAtlas(info.width, info.height, *font)) return std::move(*atlas);
    return glyphAtlas(info);
}

// Six 40-pixel sprite frames on a transparent sheet; the body bobs by a pixel every other frame.
Image8 spriteSheet(const StockMediaInfo& info) {
    Image8 image = blank(info);
    constexpr int kFrameWidth = 40, kFrames = 6;
    for (int y = 0; y < info.height; ++y)
        for (int x = 0; x < std::min(info.width, kFrameWidth * kFrames); ++x) {
            const int fx = x % kFrameWidth, bob = (x / kFrameWidth / 2) % 2, fy = y - bob;
            const bool body = fx >= 6 && fx < 28 && fy >= 8 && fy < 24;
            const bool head = fx >= 24 && fx < 36 && fy >= 12 && fy < 24;
            if (head)
                putPixel(image, x, y, 153, 153, 153, 255);
            else if (body)
                putPixel(image, x, y, 255, 153, 255, 255);
        }
    return image;
}

// High-passed white noise (each value minus its 3x3 neighbourhood mean, wrapping so it tiles),
// rank-mapped back to a flat histogram: every byte value equally often, little low-frequency
// energy. A cheap approximation; real blue noise (void-and-cluster) is not reproduced.
Image8 blueNoise(const StockMediaInfo& info) {
    Image8 image = blank(info);
    const int w = info.width, h = info.height;
    ByteStream random(seedFrom(info.hash));
    for (int c = 0; c < 4; ++c) {
        Bytes white(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
        for (auto& v : white) v = random.next();
        auto at = [&](int x, int y) -> int {
            return white[pixelIndex(w, (x + w) % w, (y + h) % h)];
        };
        constexpr int kOffset = 8 * 255;  // high-pass values lie in [-8*255, 8*255]
        std::vector<int> key(white.size()), bucketStart(16 * 255 + 2, 0);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                int neighbours = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        neighbours += (dx || dy) ? at(x + dx, y + dy) : 0;
                const int k = 8 * at(x, y) - neighbours + kOffset;
                key[pixelIndex(w, x, y)] = k;
                ++bucketStart[static_cast<std::size_t>(k) + 1];
            }
        for (std::size_t k = 1; k < bucketStart.size(); ++k) bucketStart[k] += bucketStart[k - 1];
        for (std::size_t i = 0; i < key.size(); ++i) {  // counting sort: ties ranked by position
            const auto rank =
                static_cast<std::size_t>(bucketStart[static_cast<std::size_t>(key[i])]++);
            image.rgba[i * 4 + static_cast<std::size_t>(c)] =
                static_cast<std::uint8_t>(rank * 256 / key.size());
        }
    }
    return image;
}
}  // namespace

Image8 makeStandIn(const StockMediaInfo& info) {
    Image8 image;
    if (info.kind == StockMediaKind::Noise)
        image = whiteNoise(info);
    else if (info.name == "Bayer")
        image = bayer(info);
    else if (info.name == "Font 1")
        image = fontStandIn(info);
    else if (info.name == "Nyancat")
        image = spriteSheet(info);
    else if (info.name == "Blue Noise")
        image = blueNoise(info);
    else
        image = photo(info);
    conformToChannels(image, info.channels);
    // The generators above lay rows out top first, as the real file would be; images in memory
    // are bottom first (image/Image.h).
    flipRows(std::span<std::uint8_t>(image.rgba), image.width, image.height);
    return image;
}

}  // namespace toyhost
