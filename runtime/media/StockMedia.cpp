#include "media/StockMedia.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <cstdint>
#include <vector>

namespace toyhost {

namespace {
constexpr auto Noise = StockMediaKind::Noise;
constexpr auto Photo = StockMediaKind::Photo;
constexpr auto Other = StockMediaKind::Other;

// Sizes and channel counts. Sources (facts only, read in public repositories):
//  [DS]  GabeRundlett/desktop-shadertoy src/ui/components/buffer_panel_input_window.rml: the
//        site's input picker labels per /media/a file, "W x H" and "N ch, uint8".
//  [QT]  jherico/qtvr app/resources/qml/shadertoy/Shadertoy.qml: the old site's preset tooltips
//        ("Resolution: W x H, Format: r/rgb/rgba") for /presets/texNN, mapped to the /media/a
//        hashes by beautypi/shadertoy-iOS-v2 shadertoy/ShaderInput.m (texNN <-> hash table).
//  [LEN] hbatagelo/shaderbg src/shadertoy/importer.rs: the byte length of every file. The noise
//        PNGs are incompressible, so their lengths pin size x channels: 4241 B = 64*64*1,
//        16558 B = 64*64*4, 67474 B = 256*256*1, 264082 B = 256*256*4, Blue Noise 4202841 B =
//        1024*1024*4 (each plus PNG overhead).
//  [NYAN] reindernijhoff/shadertoy nyan/Image.glsl: samples Nyancat's .w as the sprite mask and
//        steps 40-pixel frames across the 256-wide sheet, so the file has alpha.
// Where [DS] and [QT] disagree it is noted on the entry.
constexpr std::array<StockMediaInfo, 22> kStockMedia{{
    // [DS][QT] 1024x1024 rgb
    {"52d2a8f514c4fd2d9866587f4d7b2a5bfa1a11a0e772077d7682deb8b3b517e5",
     "jpg", "Abstract 1", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512 rgb
    {"bd6464771e47eed832c5eb2cd85cdc0bfc697786b903bfd30f890f9d4fc36657",
     "jpg", "Abstract 2", 512, 512, 3, Photo},
    // [DS][QT] 1024x1024 rgb
    {"8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683",
     "jpg", "Abstract 3", 1024, 1024, 3, Photo},
    // [DS][QT] 8x8, one channel
    {"85a6d68622b36995ccb98a89bbb119edf167c914660e4450d313de049320005c",
     "png", "Bayer", 8, 8, 1, Other},
    // [DS] 1024x1024 4 ch; [LEN] agrees. Blue, not white, noise: kept out of Noise.
    {"cb49c003b454385aa9975733aff4571c62182ccdda480aaba9a8d250014f00ec",
     "png", "Blue Noise", 1024, 1024, 4, Other},
    // [DS] 1024x1024 4 ch (a distance-field glyph atlas by otaviogood)
    {"08b42b43ae9d3c0605da11d0eac86618ea888e62cdd9518ee8b9097488b31560",
     "png", "Font 1", 1024, 1024, 4, Other},
    // [DS][QT][LEN] 256x256, one channel
    {"0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5",
     "png", "Gray Noise Medium", 256, 256, 1, Noise},
    // [DS][QT][LEN] 64x64, one channel
    {"0a40562379b63dfb89227e6d172f39fdce9022cba76623f1054a2c83d6c0ba5d",
     "png", "Gray Noise Small", 64, 64, 1, Noise},
    // [DS][QT] 1024x1024 rgb
    {"fb918796edc3d2221218db0811e240e72e340350008338b0c07a52bd353666a6",
     "jpg", "Lichen", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512 rgb
    {"8de3a3924cb95bd0e95a443fff0326c869f9d4979cd1d5b6e94e2a01f5be53e9",
     "jpg", "London", 512, 512, 3, Photo},
    // [DS][QT] 256x32; [DS] 4 ch, [QT] says rgb, [NYAN] shows the alpha is used: 4.
    {"cbcbb5a6cfb55c36f8f021fbb0e3f69ac96339a39fa85cd96f2017a2192821b5",
     "png", "Nyancat", 256, 32, 4, Other},
    // Organic 1-4: [DS][QT] 1024x1024 rgb
    {"cd4c518bc6ef165c39d4405b347b51ba40f8d7a065ab0e8d2e4f422cbc1e8a43",
     "jpg", "Organic 1", 1024, 1024, 3, Photo},
    {"92d7758c402f0927011ca8d0a7e40251439fba3a1dac26f5b8b62026323501aa",
     "jpg", "Organic 2", 1024, 1024, 3, Photo},
    {"79520a3d3a0f4d3caa440802ef4362e99d54e12b1392973e4ea321840970a88a",
     "jpg", "Organic 3", 1024, 1024, 3, Photo},
    {"3871e838723dd6b166e490664eead8ec60aedd6b8d95bc8e2fe3f882f0fd90f0",
     "jpg", "Organic 4", 1024, 1024, 3, Photo},
    // [DS][QT] 512x512, one channel (a grey photo)
    {"ad56fba948dfba9ae698198c109e71f118a54d209c0ea50d77ea546abad89c57",
     "png", "Pebbles", 512, 512, 1, Photo},
    // [DS][QT][LEN] 256x256 rgba
    {"f735bee5b64ef98879dc618b016ecf7939a5756040c2cde21ccb15e69a6e1cfb",
     "png", "RGBA Noise Medium", 256, 256, 4, Noise},
    // [DS][QT][LEN] 64x64 rgba
    {"3083c722c0c738cad0f468383167a0d246f91af2bfa373e9c5c094fb8c8413e0",
     "png", "RGBA Noise Small", 64, 64, 4, Noise},
    // Rock Tiles, Rusty Metal, Stars: [DS][QT] 512x512 rgb
    {"10eb4fe0ac8a7dc348a2cc282ca5df1759ab8bf680117e4047728100969e7b43",
     "jpg", "Rock Tiles", 512, 512, 3, Photo},
    {"95b90082f799f48677b4f206d856ad572f1d178c676269eac6347631d4447258",
     "jpg", "Rusty Metal", 512, 512, 3, Photo},
    {"e6e5631ce1237ae4c05b3563eda686400a401df4548d0f9fad40ecac1659c46c",
     "jpg", "Stars", 512, 512, 3, Photo},
    // [DS][QT] 1024x1024; [DS] 1 ch, [QT] rgb: unresolved, the newer [DS] label is used.
    {"1f7dca9c22f324751f2a5a59c9b181dfe3b5564a04b724c657732d0bf09c99db",
     "jpg", "Wood", 1024, 1024, 1, Photo},
}};
}  // namespace

std::span<const StockMediaInfo> stockMediaTable() { return kStockMedia; }

namespace {
char lowerAscii(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// Case-insensitive, with '_' and '-' read as spaces, so file stems like "abstract_3" match too.
bool sameName(std::string_view a, std::string_view b) {
    auto fold = [](char c) { return (c == '_' || c == '-') ? ' ' : lowerAscii(c); };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                              [&](char x, char y) { return fold(x) == fold(y); });
}

bool isImageExtension(std::string_view ext) {
    return sameName(ext, "png") || sameName(ext, "jpg") || sameName(ext, "jpeg");
}
}  // namespace

const StockMediaInfo* findStockMedia(std::string_view ref) {
    // "/media/a/<hash>.<ext>" and "<hash>.<ext>" reduce to "<hash>"; "Abstract 3.jpg" to the name.
    if (const auto slash = ref.rfind('/'); slash != std::string_view::npos)
        ref.remove_prefix(slash + 1);
    if (const auto dot = ref.rfind('.');
        dot != std::string_view::npos && isImageExtension(ref.substr(dot + 1)))
        ref.remove_suffix(ref.size() - dot);
    for (const StockMediaInfo& info : kStockMedia)
        if (sameName(ref, info.hash) || sameName(ref, info.name)) return &info;
    return nullptr;
}

std::string stockMediaPath(const StockMediaInfo& info) {
    return "/media/a/" + std::string(info.hash) + "." + std::string(info.extension);
}

// ---- Stand-ins ---------------------------------------------------------------------------------
// Everything below uses integer arithmetic only, so the bytes are identical on every compiler and
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
        image = glyphAtlas(info);
    else if (info.name == "Nyancat")
        image = spriteSheet(info);
    else if (info.name == "Blue Noise")
        image = blueNoise(info);
    else
        image = photo(info);
    conformToChannels(image, info.channels);
    return image;
}

}  // namespace toyhost
