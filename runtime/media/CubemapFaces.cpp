#include "media/CubemapFaces.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/AtomicFile.h"
#include "image/ImageFile.h"
#include "image/PixelMemory.h"

namespace toyhost {
namespace fs = std::filesystem;

const char* cubeFaceName(int face) {
    static constexpr const char* kNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    return face >= 0 && face < 6 ? kNames[face] : "?";
}

std::array<double, 3> cubeDirection(int face, double s, double t) {
    const double sc = 2 * s - 1, tc = 2 * t - 1;
    switch (static_cast<CubeFace>(face)) {
        case CubeFace::PositiveX: return {1, -tc, -sc};
        case CubeFace::NegativeX: return {-1, -tc, sc};
        case CubeFace::PositiveY: return {sc, 1, tc};
        case CubeFace::NegativeY: return {sc, -1, -tc};
        case CubeFace::PositiveZ: return {sc, -tc, 1};
        case CubeFace::NegativeZ: return {-sc, -tc, -1};
    }
    return {1, 0, 0};
}

CubeFaceCoord cubeFaceCoord(const std::array<double, 3>& d) {
    const double ax = std::abs(d[0]), ay = std::abs(d[1]), az = std::abs(d[2]);
    CubeFaceCoord out;
    double sc = 0, tc = 0, ma = 1;
    if (ax >= ay && ax >= az) {
        if (ax == 0) return CubeFaceCoord{0, 0.5, 0.5};
        ma = ax;
        out.face = d[0] >= 0 ? 0 : 1;
        sc = d[0] >= 0 ? -d[2] : d[2];
        tc = -d[1];
    } else if (ay >= az) {
        ma = ay;
        out.face = d[1] >= 0 ? 2 : 3;
        sc = d[0];
        tc = d[1] >= 0 ? d[2] : -d[2];
    } else {
        ma = az;
        out.face = d[2] >= 0 ? 4 : 5;
        sc = d[2] >= 0 ? d[0] : -d[0];
        tc = -d[1];
    }
    out.s = (sc / ma + 1) / 2;
    out.t = (tc / ma + 1) / 2;
    return out;
}

std::array<double, 3> cubeTexelDirection(int face, int size, int column, int row) {
    const double s = (column + 0.5) / size;
    // Image8 row 0 is the file's bottom row, which a vflip-false upload puts at t = 1.
    const double t = 1.0 - (row + 0.5) / size;
    return cubeDirection(face, s, t);
}

namespace {

struct Colour {
    double r, g, b;
};

Colour mix(const Colour& a, const Colour& b, double k) {
    return {a.r + (b.r - a.r) * k, a.g + (b.g - a.g) * k, a.b + (b.b - a.b) * k};
}

double smoothstep(double edge0, double edge1, double x) {
    const double k = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return k * k * (3 - 2 * k);
}

std::uint8_t toByte(double v) { return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

// The stand-in environment in one direction (normalised).
Colour skyColour(double x, double y, double z) {
    constexpr Colour kZenith{0.16, 0.36, 0.78}, kHorizonSky{0.70, 0.82, 0.95};
    constexpr Colour kGroundNear{0.42, 0.37, 0.30}, kNadir{0.15, 0.12, 0.10};
    const Colour sky = mix(kHorizonSky, kZenith, std::pow(std::max(y, 0.0), 0.45));
    const Colour ground = mix(kGroundNear, kNadir, std::pow(std::max(-y, 0.0), 0.6));
    // A soft edge a couple of degrees wide instead of a hard horizon line.
    Colour c = mix(ground, sky, smoothstep(-0.03, 0.01, y));

    // Longitude tint: cos(phi + a) from the horizontal direction without atan2.
    const double horizontal = std::sqrt(x * x + z * z);
    const double cosPhi = horizontal > 1e-9 ? x / horizontal : 1.0;
    const double sinPhi = horizontal > 1e-9 ? z / horizontal : 0.0;
    auto turned = [&](double a) { return cosPhi * std::cos(a) - sinPhi * std::sin(a); };
    const double tint = y > -0.03 ? 1.0 : 0.5;  // fainter on the ground
    c.r *= 1 + 0.06 * tint * turned(0.0);
    c.g *= 1 + 0.03 * tint * turned(2.1);
    c.b *= 1 + 0.06 * tint * turned(4.2);

    // Haze: brighter toward the horizon from both sides.
    const double haze = std::exp(-std::abs(y) * 18.0);
    c.r += 0.22 * haze, c.g += 0.20 * haze, c.b += 0.16 * haze;

    // A soft sun with a wide glow.
    static const double kSunLength = std::sqrt(0.5 * 0.5 + 0.35 * 0.35 + 0.8 * 0.8);
    const double facing = std::max(0.0, (-0.5 * x + 0.35 * y - 0.8 * z) / kSunLength);
    const double glow = 0.35 * std::pow(facing, 12.0) + (facing > 0.9 ? 3.0 * std::pow(facing, 800.0) : 0.0);
    c.r += 1.00 * glow, c.g += 0.90 * glow, c.b += 0.70 * glow;
    return c;
}

}  // namespace

CubeFaces8 cubemapStandIn(int size) {
    size = std::max(size, 1);
    CubeFaces8 cube;
    cube.size = size;
    for (int face = 0; face < 6; ++face) {
        Image8& image = cube.faces[face];
        image.width = size;
        image.height = size;
        image.rgba.resize(frameBytes(size, size, PixelFormat::Rgba8));
        std::uint8_t* p = image.rgba.data();
        for (int row = 0; row < size; ++row) {
            for (int column = 0; column < size; ++column, p += 4) {
                const std::array<double, 3> d = cubeTexelDirection(face, size, column, row);
                const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                const Colour c = skyColour(d[0] / length, d[1] / length, d[2] / length);
                p[0] = toByte(c.r), p[1] = toByte(c.g), p[2] = toByte(c.b), p[3] = 255;
            }
        }
    }
    return cube;
}

fs::path cubemapFacePath(const fs::path& face0, int face) {
    if (face == 0) return face0;
    // The site splits at the last '.' of the name: "x.tar.png" -> "x.tar_1.png"; no extension -> "x_1".
    const std::string name = face0.filename().string();
    const std::size_t dot = name.rfind('.');
    const std::string numbered = dot == std::string::npos || dot == 0
                                     ? name + "_" + std::to_string(face)
                                     : name.substr(0, dot) + "_" + std::to_string(face) + name.substr(dot);
    return face0.parent_path() / numbered;
}

Result<CubeFaces8> loadCubemapFaces(const fs::path& face0) {
    std::vector<Diagnostic> problems;
    CubeFaces8 cube;
    for (int face = 0; face < 6; ++face) {
        const fs::path path = cubemapFacePath(face0, face);
        const std::string what = std::string("cubemap face ") + std::to_string(face) + " (" + cubeFaceName(face) + ")";
        if (Status regular = checkRegularFile(path, what); !regular) {
            problems.insert(problems.end(), regular.error().diagnostics.begin(), regular.error().diagnostics.end());
            continue;
        }
        Result<Image8> image = loadImageFile(path);
        if (!image) {
            for (Diagnostic d : image.error().diagnostics) {
                d.message = what + ": " + d.message;
                problems.push_back(std::move(d));
            }
            continue;
        }
        cube.faces[face] = std::move(*image);
    }
    if (!problems.empty()) return Error(std::move(problems));

    cube.size = cube.faces[0].width;
    for (int face = 0; face < 6; ++face) {
        const Image8& image = cube.faces[face];
        const std::string what = std::string("cubemap face ") + std::to_string(face) + " (" + cubeFaceName(face) + ")";
        const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
        if (image.width != image.height)
            problems.push_back(fileError(cubemapFacePath(face0, face).string(),
                                         what + " is " + size + "; cube faces must be square", Code::CubemapFaceSize)
                                   .first());
        else if (face > 0 && image.width != cube.size)
            problems.push_back(fileError(cubemapFacePath(face0, face).string(),
                                         what + " is " + size + " but face 0 is " + std::to_string(cube.size) + "x" +
                                             std::to_string(cube.faces[0].height) + "; all six faces must be the same size",
                                         Code::CubemapFaceSize)
                                   .first());
    }
    if (!problems.empty()) return Error(std::move(problems));
    return cube;
}

namespace {

enum class CrossLayout { HorizontalCross, VerticalCross, HorizontalStrip, VerticalStrip };

// Where a face's square sits in a layout: its column and row counted in squares from the top left,
// and whether it is stored rotated by 180 degrees.
struct FaceCell {
    int column;
    int row;
    bool rotated;
};

FaceCell cellOf(CrossLayout layout, int face) {
    switch (layout) {
        case CrossLayout::HorizontalCross: {
            static constexpr FaceCell kCells[6] = {{2, 1, false}, {0, 1, false}, {1, 0, false},
                                                   {1, 2, false}, {1, 1, false}, {3, 1, false}};
            return kCells[face];
        }
        case CrossLayout::VerticalCross: {
            static constexpr FaceCell kCells[6] = {{2, 1, false}, {0, 1, false}, {1, 0, false},
                                                   {1, 2, false}, {1, 1, false}, {1, 3, true}};
            return kCells[face];
        }
        case CrossLayout::HorizontalStrip: return {face, 0, false};
        case CrossLayout::VerticalStrip: return {0, face, false};
    }
    return {0, 0, false};
}

}  // namespace

Result<CubeFaces8> cubemapFromCross(const Image8& image) {
    const int w = image.width, h = image.height;
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    if (w <= 0 || h <= 0 || image.rgba.size() != frameBytes(w, h, PixelFormat::Rgba8))
        return Error("the cubemap image is empty or its pixels do not match its " + size + " size", Code::CubemapLayout);
    CrossLayout layout;
    int n = 0;
    if (3 * w == 4 * h && w % 4 == 0) layout = CrossLayout::HorizontalCross, n = w / 4;
    else if (4 * w == 3 * h && w % 3 == 0) layout = CrossLayout::VerticalCross, n = w / 3;
    else if (w == 6 * h) layout = CrossLayout::HorizontalStrip, n = h;
    else if (h == 6 * w) layout = CrossLayout::VerticalStrip, n = w;
    else
        return Error("a cubemap image " + size +
                         " has none of the supported layouts: a horizontal cross (4:3, faces n x n with width 4n), "
                         "a vertical cross (3:4), a horizontal strip (6:1) or a vertical strip (1:6)",
                     Code::CubemapLayout);

    const int squaresDown = h / n;
    const std::size_t rowBytes = static_cast<std::size_t>(w) * 4, faceRowBytes = static_cast<std::size_t>(n) * 4;
    CubeFaces8 cube;
    cube.size = n;
    for (int face = 0; face < 6; ++face) {
        const FaceCell cell = cellOf(layout, face);
        Image8& out = cube.faces[face];
        out.width = n;
        out.height = n;
        if (!tryResize(out.rgba, frameBytes(n, n, PixelFormat::Rgba8)))
            return notEnoughMemory("", "cutting the cubemap image into faces", pictureMemoryText(n, n, 6, "faces"));
        // Rows are bottom first: the square in row `cell.row` from the top starts at this Image8 row.
        const int bottomRow = (squaresDown - 1 - cell.row) * n;
        const std::uint8_t* source = image.rgba.data() + static_cast<std::size_t>(cell.column) * faceRowBytes;
        for (int y = 0; y < n; ++y) {
            std::uint8_t* target = out.rgba.data() + static_cast<std::size_t>(y) * faceRowBytes;
            if (!cell.rotated) {
                std::memcpy(target, source + static_cast<std::size_t>(bottomRow + y) * rowBytes, faceRowBytes);
                continue;
            }
            const std::uint8_t* from = source + static_cast<std::size_t>(bottomRow + n - 1 - y) * rowBytes;
            for (int x = 0; x < n; ++x) std::memcpy(target + x * 4, from + static_cast<std::size_t>(n - 1 - x) * 4, 4);
        }
    }
    return cube;
}

}  // namespace toyhost
