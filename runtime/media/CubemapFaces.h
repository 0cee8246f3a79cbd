// CubemapFaces: the six faces of a `cubemap` channel on the CPU: a stock cubemap's six files, a
// user's single cross or strip image cut into faces, a deterministic sky stand-in, and the GL
// face/direction convention they follow. The renderer uploads them. No GL needed.
#pragma once

#include <array>
#include <filesystem>

#include "core/Result.h"
#include "image/Image.h"

namespace toyhost {

// GL's face order (TEXTURE_CUBE_MAP_POSITIVE_X + i): +X, -X, +Y, -Y, +Z, -Z.
enum class CubeFace { PositiveX, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };
const char* cubeFaceName(int face);  // "+X", "-X", "+Y", "-Y", "+Z", "-Z"

// Each face is size x size RGBA8 and, like every Image8, rows bottom first: face i holds the picture
// of the site's face file i (files are top row first), so flipRows() gives back the file's rows.
//
// How the site uploads them (piLibs.js CreateTextureFromImage and SetSamplerVFlip, TEXTYPE.CUBEMAP
// branch, as mirrored in public repositories; stock cubemaps through effect.js NewTexture, which
// loads file i into image[i]):
// - vflip false (every cubemap input in the exports seen has "vflip": "false"): file i goes to GL
//   face i with its TOP row first, i.e. at t = 0. Upload flipRows() of our faces. Then cube
//   lookups match the picture: a side face's top row is the world's up (ry = +1, tc = -ry).
// - vflip true: UNPACK_FLIP_Y_WEBGL on every face (our bottom-first rows uploaded as they are) AND
//   the two Y files swapped: +Y gets file 3, -Y gets file 2. Together that is the environment
//   mirrored top to bottom (direction (x, y, z) shows what vflip false shows at (x, -y, z)).
// - The channel's filter is applied (mipmap: mipmaps generated once, at upload); its wrap never is
//   (SetSamplerWrap handles 2D and 3D textures only).
// Tests: tests/io/test_cubemap_faces.cpp.
struct CubeFaces8 {
    int size = 0;
    std::array<Image8, 6> faces;  // GL face order
};

// A point on a face: s across (left to right as the face file shows it), t down (t = 0 is the
// file's top row when uploaded with vflip false), both 0..1.
struct CubeFaceCoord {
    int face = 0;
    double s = 0;
    double t = 0;
};

// The direction (not normalised) that samples (s, t) of `face`: the inverse of the OpenGL ES 3.0
// table "Selection of cube map images" (+X: sc = -rz, tc = -ry; -X: sc = +rz, tc = -ry;
// +Y: sc = +rx, tc = +rz; -Y: sc = +rx, tc = -rz; +Z: sc = +rx, tc = -ry; -Z: sc = -rx, tc = -ry;
// s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2).
std::array<double, 3> cubeDirection(int face, double s, double t);
// The face and (s, t) GL samples for `direction`: its major axis (the largest magnitude; ties go to
// x, then y) picks the face, then the table above. The zero vector gives +X at the centre.
CubeFaceCoord cubeFaceCoord(const std::array<double, 3>& direction);
// The direction through the centre of texel (column, row) of face `face` of a cube of `size`, `row`
// counted in Image8 order (bottom first), as the site's vflip-false upload samples it.
std::array<double, 3> cubeTexelDirection(int face, int size, int column, int row);

// A deterministic sky-like environment of six size x size faces (the same bytes on every run):
// a sky darkening toward the zenith above the horizon (y > 0), a bright haze band along the
// horizon, ground below that darkens toward the nadir, a soft sun toward (-0.5, 0.35, -0.8), and a
// faint tint that turns with longitude, so reflections and refractions read as such. Each texel is
// computed from cubeTexelDirection(). Alpha 255.
CubeFaces8 cubemapStandIn(int size);

// The site's stock cubemaps are six files: `face0` for face 0 and the same name with "_1" .. "_5"
// before the extension for faces 1..5 (effect.js: src.substring(0, lastIndexOf('.')) + "_" + i +
// extension). Decodes all six with loadImageFile. Every problem is reported, each naming its file:
// missing or undecodable faces, a face that is not square, a face whose size differs from face 0.
Result<CubeFaces8> loadCubemapFaces(const std::filesystem::path& face0);
// The file of face `face` (0..5) of the stock cubemap whose face-0 file is `face0`.
std::filesystem::path cubemapFacePath(const std::filesystem::path& face0, int face);

// A single image holding all six faces, the layout found from its aspect ratio (n = face size),
// each face upright as its own face file would be (top of the square = t = 0):
//   horizontal cross, 4n x 3n:  row 1 (top):  .   +Y   .   .
//                               row 2:       -X   +Z  +X  -Z
//                               row 3:        .   -Y   .   .
//   vertical cross, 3n x 4n:    rows top to bottom: [. +Y .], [-X +Z +X], [. -Y .], [. -Z .],
//                               the -Z square rotated 180 degrees (it continues below -Y)
//   horizontal strip, 6n x n:   +X -X +Y -Y +Z -Z left to right
//   vertical strip, n x 6n:     +X -X +Y -Y +Z -Z top to bottom
// Any other shape is refused with a message that lists these. `image` is rows bottom first.
Result<CubeFaces8> cubemapFromCross(const Image8& image);

}  // namespace toyhost
