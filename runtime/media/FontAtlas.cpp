#include "media/FontAtlas.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace toyhost {

namespace {

constexpr double kInfinity = 1e20;

// Squared distance to the nearest zero of f along one line (Felzenszwalb and Huttenlocher's
// lower envelope of parabolas), in place.
void distance1d(std::vector<double>& f, std::vector<double>& out, std::vector<int>& v, std::vector<double>& z) {
    const int n = static_cast<int>(f.size());
    int k = 0;
    v[0] = 0;
    z[0] = -kInfinity;
    z[1] = kInfinity;
    for (int q = 1; q < n; ++q) {
        double s = 0;
        for (;;) {
            const int p = v[static_cast<std::size_t>(k)];
            s = ((f[static_cast<std::size_t>(q)] + q * q) - (f[static_cast<std::size_t>(p)] + p * p)) / (2.0 * (q - p));
            if (s > z[static_cast<std::size_t>(k)] || k == 0) break;
            --k;
        }
        if (s <= z[static_cast<std::size_t>(k)]) s = z[static_cast<std::size_t>(k)];
        ++k;
        v[static_cast<std::size_t>(k)] = q;
        z[static_cast<std::size_t>(k)] = s;
        z[static_cast<std::size_t>(k) + 1] = kInfinity;
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[static_cast<std::size_t>(k) + 1] < q) ++k;
        const int p = v[static_cast<std::size_t>(k)];
        out[static_cast<std::size_t>(q)] = (q - p) * (q - p) + f[static_cast<std::size_t>(p)];
    }
}

// Euclidean distance from every pixel to the nearest pixel where `inside` is set.
std::vector<double> distanceTo(const std::vector<bool>& inside, int width, int height) {
    std::vector<double> grid(inside.size());
    for (std::size_t i = 0; i < inside.size(); ++i) grid[i] = inside[i] ? 0.0 : kInfinity;
    const int longest = std::max(width, height);
    std::vector<double> f(static_cast<std::size_t>(longest)), out(static_cast<std::size_t>(longest));
    std::vector<int> v(static_cast<std::size_t>(longest));
    std::vector<double> z(static_cast<std::size_t>(longest) + 1);
    auto at = [&](int x, int y) -> double& { return grid[static_cast<std::size_t>(y) * width + x]; };
    f.resize(static_cast<std::size_t>(height));
    out.resize(static_cast<std::size_t>(height));
    for (int x = 0; x < width; ++x) {
        for (int y = 0; y < height; ++y) f[static_cast<std::size_t>(y)] = at(x, y);
        distance1d(f, out, v, z);
        for (int y = 0; y < height; ++y) at(x, y) = out[static_cast<std::size_t>(y)];
    }
    f.resize(static_cast<std::size_t>(width));
    out.resize(static_cast<std::size_t>(width));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) f[static_cast<std::size_t>(x)] = at(x, y);
        distance1d(f, out, v, z);
        for (int x = 0; x < width; ++x) at(x, y) = std::sqrt(out[static_cast<std::size_t>(x)]);
    }
    return grid;
}

std::uint8_t biased(double value) {  // 127/255 + value, in bytes, clamped
    return static_cast<std::uint8_t>(std::clamp(std::lround(127.0 + value * 255.0), 0L, 255L));
}

}  // namespace

std::optional<std::filesystem::path> atlasFontFile() {
    for (const char* file : {"/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
                             "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"}) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(file, ec)) return std::filesystem::path(file);
    }
    return std::nullopt;
}

Result<Image8> fontAtlas(int width, int height, const std::filesystem::path& font) {
    if (width % 16 != 0 || height % 16 != 0 || width < 16 || height < 16)
        return Error("font atlas: " + std::to_string(width) + "x" + std::to_string(height) +
                         " is not a grid of 16 x 16 cells",
                     Code::Internal);
    FT_Library library = nullptr;
    if (FT_Init_FreeType(&library) != 0) return Error("font atlas: FreeType did not start", Code::Internal);
    FT_Face face = nullptr;
    if (FT_New_Face(library, font.c_str(), 0, &face) != 0) {
        FT_Done_FreeType(library);
        return fileError(font.string(), "FreeType cannot read this font", Code::ImageDecode);
    }
    const int cellW = width / 16, cellH = height / 16;
    // An em of 3/4 of the cell: capitals take about half its height, centred, as the site's do.
    FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(cellH * 3 / 4));
    const int capHeight = cellH * 3 / 4 * 73 / 100;  // DejaVu's capitals are 0.73 em
    const int baseline = (cellH + capHeight) / 2;      // from the cell's top

    std::vector<std::uint8_t> coverage(static_cast<std::size_t>(width) * height, 0);
    for (int code = 33; code < 256; ++code) {
        if (code >= 127 && code < 161) continue;  // DEL and the C1 controls have no glyph
        if (FT_Load_Char(face, static_cast<FT_ULong>(code), FT_LOAD_RENDER) != 0) continue;
        const FT_GlyphSlot glyph = face->glyph;
        const FT_Bitmap& bitmap = glyph->bitmap;
        const int cellX = (code % 16) * cellW, cellY = (code / 16) * cellH;
        const int advance = static_cast<int>(glyph->advance.x >> 6);
        const int left = cellX + (cellW - advance) / 2 + glyph->bitmap_left;
        const int top = cellY + baseline - glyph->bitmap_top;
        for (unsigned row = 0; row < bitmap.rows; ++row)
            for (unsigned col = 0; col < bitmap.width; ++col) {
                const int x = left + static_cast<int>(col), y = top + static_cast<int>(row);
                if (x < cellX || x >= cellX + cellW || y < cellY || y >= cellY + cellH) continue;
                coverage[static_cast<std::size_t>(y) * width + x] =
                    bitmap.buffer[static_cast<std::ptrdiff_t>(row) * bitmap.pitch + col];
            }
    }
    FT_Done_Face(face);
    FT_Done_FreeType(library);

    // Signed distance to the outline (coverage 1/2), negative inside, in cells.
    std::vector<bool> in(coverage.size()), out(coverage.size());
    for (std::size_t i = 0; i < coverage.size(); ++i) {
        in[i] = coverage[i] >= 128;
        out[i] = !in[i];
    }
    const std::vector<double> toInside = distanceTo(in, width, height);
    const std::vector<double> toOutside = distanceTo(out, width, height);
    std::vector<double> signedDistance(coverage.size());
    for (std::size_t i = 0; i < coverage.size(); ++i)
        signedDistance[i] = (in[i] ? 0.5 - toOutside[i] : toInside[i] - 0.5) / cellH;

    Image8 image{width, height, std::vector<std::uint8_t>(coverage.size() * 4)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            auto d = [&](int dx, int dy) {
                const int cx = std::clamp(x + dx, 0, width - 1), cy = std::clamp(y + dy, 0, height - 1);
                return signedDistance[static_cast<std::size_t>(cy) * width + cx];
            };
            double gx = d(1, 0) - d(-1, 0), gy = d(0, 1) - d(0, -1);
            const double length = std::hypot(gx, gy);
            if (length > 0) {
                gx /= length;
                gy /= length;
            }
            image.rgba[i * 4 + 0] = coverage[i];
            image.rgba[i * 4 + 1] = biased(gx * 0.49);
            image.rgba[i * 4 + 2] = biased(gy * 0.49);
            image.rgba[i * 4 + 3] = biased(signedDistance[i]);
        }
    return image;
}

}  // namespace toyhost
