// CubemapFaces: the GL face/direction convention, the sky stand-in, stock cubemaps as six files,
// and single cross/strip images cut into faces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "DiagnosticText.h"
#include "TestFolder.h"
#include "image/ImageWriters.h"
#include "media/CubemapFaces.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {

std::array<std::uint8_t, 4> texel(const Image8& image, int column, int row) {
    const std::size_t at = (static_cast<std::size_t>(row) * image.width + column) * 4;
    return {image.rgba[at], image.rgba[at + 1], image.rgba[at + 2], image.rgba[at + 3]};
}

Image8 solid(int width, int height, std::array<std::uint8_t, 4> colour) {
    Image8 image{width, height, {}};
    for (int i = 0; i < width * height; ++i) image.rgba.insert(image.rgba.end(), colour.begin(), colour.end());
    return image;
}

// A distinct colour per face.
std::array<std::uint8_t, 4> faceColour(int face) {
    return {static_cast<std::uint8_t>(40 * face + 20), static_cast<std::uint8_t>(200 - 30 * face), 77, 255};
}

// Paints a square of an Image8 given in picture coordinates (column, row counted from the top
// left, in squares of n), with a white marker at the square's top-left texel.
void paintSquare(Image8& image, int n, int column, int row, std::array<std::uint8_t, 4> colour) {
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int fromTop = row * n + y;
            const std::size_t at =
                (static_cast<std::size_t>(image.height - 1 - fromTop) * image.width + column * n + x) * 4;
            const bool marker = x == 0 && y == 0;
            for (int c = 0; c < 4; ++c) image.rgba[at + c] = marker ? 255 : colour[c];
        }
}

Image8 blank(int width, int height) { return Image8{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4, 0)}; }

// Face `face` is its colour, with the marker where the face file's top-left texel is (Image8 row
// n-1, column 0), or at the opposite corner when the layout stored it rotated by 180 degrees.
void expectFace(const CubeFaces8& cube, int face, bool rotated = false) {
    const Image8& image = cube.faces[face];
    const int n = cube.size;
    ASSERT_EQ(image.width, n);
    ASSERT_EQ(image.height, n);
    const int markerColumn = rotated ? n - 1 : 0, markerRow = rotated ? 0 : n - 1;
    EXPECT_EQ(texel(image, markerColumn, markerRow), (std::array<std::uint8_t, 4>{255, 255, 255, 255}))
        << "face " << cubeFaceName(face);
    EXPECT_EQ(texel(image, n / 2, n / 2), faceColour(face)) << "face " << cubeFaceName(face);
    EXPECT_EQ(texel(image, rotated ? 0 : n - 1, rotated ? n - 1 : 0), faceColour(face)) << "face " << cubeFaceName(face);
}

double brightness(const std::array<std::uint8_t, 4>& c) { return c[0] + c[1] + c[2]; }

}  // namespace

TEST(CubeDirections, TheSpecTableForOnePointPerFace) {
    // Hand-computed from the OpenGL ES 3.0 table "Selection of cube map images".
    struct Case {
        std::array<double, 3> direction;
        int face;
        double s, t;
    };
    const Case cases[] = {
        {{1, 0.5, -0.25}, 0, 0.625, 0.25},   // +X: sc = -rz, tc = -ry
        {{-2, 1, 1}, 1, 0.75, 0.25},         // -X: sc = +rz, tc = -ry
        {{0.5, 1, -0.5}, 2, 0.75, 0.25},     // +Y: sc = +rx, tc = +rz
        {{0.5, -1, -0.5}, 3, 0.75, 0.75},    // -Y: sc = +rx, tc = -rz
        {{-0.4, 0.2, 1}, 4, 0.3, 0.4},       // +Z: sc = +rx, tc = -ry
        {{0.3, -0.2, -1}, 5, 0.35, 0.6},     // -Z: sc = -rx, tc = -ry
    };
    for (const Case& c : cases) {
        const CubeFaceCoord coord = cubeFaceCoord(c.direction);
        EXPECT_EQ(coord.face, c.face);
        EXPECT_NEAR(coord.s, c.s, 1e-12) << cubeFaceName(c.face);
        EXPECT_NEAR(coord.t, c.t, 1e-12) << cubeFaceName(c.face);
    }
    EXPECT_EQ(cubeDirection(0, 0.5, 0.5), (std::array<double, 3>{1, 0, 0}));
    EXPECT_EQ(cubeDirection(5, 0.5, 0.5), (std::array<double, 3>{0, 0, -1}));
}

TEST(CubeDirections, EveryTexelCentreRoundTripsThroughTheMajorAxisRule) {
    const int n = 16;
    for (int face = 0; face < 6; ++face)
        for (int row = 0; row < n; ++row)
            for (int column = 0; column < n; ++column) {
                const CubeFaceCoord back = cubeFaceCoord(cubeTexelDirection(face, n, column, row));
                ASSERT_EQ(back.face, face) << column << "," << row;
                EXPECT_NEAR(back.s, (column + 0.5) / n, 1e-12);
                EXPECT_NEAR(back.t, 1.0 - (row + 0.5) / n, 1e-12);  // Image8 rows are bottom first
            }
}

TEST(CubeDirections, AFaceFilesTopRowLooksUpAndTheTopFaceMeetsMinusZAtItsTop) {
    const int n = 8;
    for (int face : {0, 1, 4, 5}) {  // the four side faces: the file's top row (Image8 row n-1) is up
        EXPECT_GT(cubeTexelDirection(face, n, n / 2, n - 1)[1], 0.8) << cubeFaceName(face);
        EXPECT_LT(cubeTexelDirection(face, n, n / 2, 0)[1], -0.8) << cubeFaceName(face);
    }
    EXPECT_LT(cubeTexelDirection(2, n, n / 2, n - 1)[2], -0.8);  // +Y's top edge adjoins -Z
    EXPECT_GT(cubeTexelDirection(3, n, n / 2, n - 1)[2], 0.8);   // -Y's top edge adjoins +Z
    // +Z's right edge adjoins +X, as in the horizontal cross.
    EXPECT_GT(cubeTexelDirection(4, n, n - 1, n / 2)[0], 0.8);
}

TEST(CubemapStandIn, IsDeterministicAndFacesDiffer) {
    const CubeFaces8 a = cubemapStandIn(32), b = cubemapStandIn(32);
    EXPECT_EQ(a.size, 32);
    for (int face = 0; face < 6; ++face) {
        EXPECT_EQ(a.faces[face].width, 32);
        EXPECT_EQ(a.faces[face].height, 32);
        EXPECT_EQ(a.faces[face].rgba, b.faces[face].rgba);
        for (int other = 0; other < face; ++other) EXPECT_NE(a.faces[face].rgba, a.faces[other].rgba);
        for (std::size_t i = 3; i < a.faces[face].rgba.size(); i += 4) ASSERT_EQ(a.faces[face].rgba[i], 255);
    }
}

TEST(CubemapStandIn, SkyAboveTheHorizonIsBrighterAndBluerThanTheGroundBelow) {
    const int n = 64;
    const CubeFaces8 cube = cubemapStandIn(n);
    for (int face : {0, 1, 4, 5}) {
        // Rows n/2 + 3 and n/2 - 4 look about 0.11 above and below the horizon.
        const auto up = texel(cube.faces[face], n / 2, n / 2 + 3), down = texel(cube.faces[face], n / 2, n / 2 - 4);
        ASSERT_GT(cubeTexelDirection(face, n, n / 2, n / 2 + 3)[1], 0.1);
        ASSERT_LT(cubeTexelDirection(face, n, n / 2, n / 2 - 4)[1], -0.1);
        EXPECT_GT(brightness(up), brightness(down)) << cubeFaceName(face);
        EXPECT_GT(up[2] - up[0], down[2] - down[0]) << cubeFaceName(face);
    }
    // The zenith is a deeper blue than the sky near the horizon.
    const auto zenith = texel(cube.faces[2], n / 2, n / 2), horizon = texel(cube.faces[4], n / 2, n / 2 + 3);
    EXPECT_LT(brightness(zenith), brightness(horizon));
    EXPECT_GT(zenith[2], zenith[0]);
}

TEST(CubemapFiles, FaceNamesFollowTheSite) {
    EXPECT_EQ(cubemapFacePath("/m/a/abc.png", 0), fs::path("/m/a/abc.png"));
    EXPECT_EQ(cubemapFacePath("/m/a/abc.png", 3), fs::path("/m/a/abc_3.png"));
    EXPECT_EQ(cubemapFacePath("x.tar.jpg", 5), fs::path("x.tar_5.jpg"));
    EXPECT_EQ(cubemapFacePath("sky", 1), fs::path("sky_1"));
}

class CubemapFilesTest : public ::testing::Test {
protected:
    // Six 8x8 PNG faces, each its face colour, column 0 of each file's top half red 255.
    void SetUp() override {
        for (int face = 0; face < 6; ++face) writeFace(face, 8, 8);
    }
    void writeFace(int face, int width, int height) {
        Image8 image = solid(width, height, faceColour(face));
        for (int row = height / 2; row < height; ++row) image.rgba[(std::size_t(row) * width) * 4] = 255;  // top half
        const Status written = writePng(cubemapFacePath(face0(), face), width, height, image.rgba);
        ASSERT_TRUE(written) << written.error().text();
    }
    fs::path face0() const { return folder.path / "cube.png"; }
    TestFolder folder;
};

TEST_F(CubemapFilesTest, SixFilesLoadInGlFaceOrder) {
    Result<CubeFaces8> cube = loadCubemapFaces(face0());
    ASSERT_TRUE(cube) << cube.error().text();
    EXPECT_EQ(cube->size, 8);
    for (int face = 0; face < 6; ++face) {
        EXPECT_EQ(texel(cube->faces[face], 1, 1), faceColour(face)) << face;  // bottom half: as painted
        EXPECT_EQ(texel(cube->faces[face], 0, 7)[0], 255) << face;           // top row holds the marker
    }
}

TEST_F(CubemapFilesTest, AMissingFaceIsNamed) {
    fs::remove(cubemapFacePath(face0(), 3));
    Result<CubeFaces8> cube = loadCubemapFaces(face0());
    ASSERT_FALSE(cube);
    EXPECT_EQ(toyhost::testing::plainText(cube.error()),
              (folder.path / "cube_3.png").string() + ": cubemap face 3 (-Y) file not found");
}

TEST_F(CubemapFilesTest, NonSquareAndMismatchedFacesAreRefused) {
    writeFace(2, 8, 6);
    writeFace(4, 16, 16);
    Result<CubeFaces8> cube = loadCubemapFaces(face0());
    ASSERT_FALSE(cube);
    EXPECT_EQ(toyhost::testing::plainText(cube.error()),
              (folder.path / "cube_2.png").string() + ": cubemap face 2 (+Y) is 8x6; cube faces must be square\n" +
                  (folder.path / "cube_4.png").string() +
                  ": cubemap face 4 (+Z) is 16x16 but face 0 is 8x8; all six faces must be the same size");
}

TEST_F(CubemapFilesTest, AnUndecodableFaceIsNamed) {
    folder.write("cube_5.png", "not a png");
    Result<CubeFaces8> cube = loadCubemapFaces(face0());
    ASSERT_FALSE(cube);
    ASSERT_EQ(cube.error().diagnostics.size(), 1u);
    EXPECT_EQ(cube.error().first().file, (folder.path / "cube_5.png").string());
    EXPECT_NE(cube.error().first().message.find("cubemap face 5 (-Z): cannot decode image"), std::string::npos)
        << cube.error().first().message;
}

TEST(CubemapCross, HorizontalCross) {
    const int n = 4;
    Image8 image = blank(4 * n, 3 * n);
    const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {3, 1}};  // +X -X +Y -Y +Z -Z
    for (int face = 0; face < 6; ++face) paintSquare(image, n, cells[face][0], cells[face][1], faceColour(face));
    Result<CubeFaces8> cube = cubemapFromCross(image);
    ASSERT_TRUE(cube) << cube.error().text();
    EXPECT_EQ(cube->size, n);
    for (int face = 0; face < 6; ++face) expectFace(*cube, face);
}

TEST(CubemapCross, VerticalCrossWithMinusZUpsideDown) {
    const int n = 4;
    Image8 image = blank(3 * n, 4 * n);
    const int cells[6][2] = {{2, 1}, {0, 1}, {1, 0}, {1, 2}, {1, 1}, {1, 3}};
    for (int face = 0; face < 6; ++face) paintSquare(image, n, cells[face][0], cells[face][1], faceColour(face));
    Result<CubeFaces8> cube = cubemapFromCross(image);
    ASSERT_TRUE(cube) << cube.error().text();
    for (int face = 0; face < 5; ++face) expectFace(*cube, face);
    // The square's top-left marker is the -Z face's bottom-right once turned upright.
    expectFace(*cube, 5, /*rotated=*/true);
}

TEST(CubemapCross, StripsAreInGlFaceOrder) {
    const int n = 4;
    Image8 horizontal = blank(6 * n, n), vertical = blank(n, 6 * n);
    for (int face = 0; face < 6; ++face) {
        paintSquare(horizontal, n, face, 0, faceColour(face));
        paintSquare(vertical, n, 0, face, faceColour(face));
    }
    for (const Image8* image : {&horizontal, &vertical}) {
        Result<CubeFaces8> cube = cubemapFromCross(*image);
        ASSERT_TRUE(cube) << cube.error().text();
        for (int face = 0; face < 6; ++face) expectFace(*cube, face);
    }
}

TEST(CubemapCross, OtherShapesAreRefused) {
    Result<CubeFaces8> cube = cubemapFromCross(blank(500, 300));
    ASSERT_FALSE(cube);
    EXPECT_EQ(toyhost::testing::plainText(cube.error()),
              "a cubemap image 500x300 has none of the supported layouts: a horizontal cross (4:3, faces n x n with "
              "width 4n), a vertical cross (3:4), a horizontal strip (6:1) or a vertical strip (1:6)");
    EXPECT_FALSE(cubemapFromCross(blank(10, 10)));
    EXPECT_FALSE(cubemapFromCross(blank(0, 0)));
}
