// Tiled stills (session/TiledStill.h): a canvas beyond one framebuffer is drawn in tiles with
// iResolution the whole canvas and written band by band. A tiled render equals the untiled one
// byte for byte (PNG, with Cube A too, and EXR floats with supersampling); a 20000x11250 still of
// fragCoord / iResolution has the expected values at its corners and centre while the run's
// peak memory stays under 1 GB; tiles keep the canvas's 2x2 derivative quads; shadertoys with buffers, windows and videos are refused with why.
#include "GlTestSupport.h"

#include <png.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kProbe = sourceDir() / "shadertoys/tile-probe";
const fs::path kSampling = sourceDir() / "shadertoys/sampling-probe";

CommandResult run(const fs::path& target, const std::string& flags) {
    return runToyhost("run " + target.string() + " --headless --quiet --date 2024-01-01T00:00:00 " + flags);
}

TEST(TiledStill, ATiledRenderEqualsTheUntiledOneByteForByte) {
    const fs::path dir = freshOutputDir("tiled-still-equal");
    // Tiles of 1024 over 4096x2304 (the last band is a partial one: 2304 = 2 x 1024 + 256).
    const CommandResult tiled = run(kProbe, "--size 4096x2304 --tile 1024 --out " + (dir / "tiled.png").string());
    ASSERT_EQ(tiled.exitCode, 0) << tiled.output;
    const CommandResult whole = run(kProbe, "--size 4096x2304 --out " + (dir / "whole.png").string());
    ASSERT_EQ(whole.exitCode, 0) << whole.output;
    Result<Image8> a = readPng(dir / "tiled.png");
    Result<Image8> b = readPng(dir / "whole.png");
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->width, 4096);
    EXPECT_EQ(a->height, 2304);
    EXPECT_TRUE(a->rgba == b->rgba);
    // Cube A (canvas-independent, run once a frame) with tiles: the same picture.
    const std::string cube = "--size 300x170 --frames 3 --out ";
    const fs::path cubeProbe = sourceDir() / "shadertoys/cube-probe";
    ASSERT_EQ(run(cubeProbe, cube + (dir / "ct_%d.png").string() + " --tile 64").exitCode, 0);
    ASSERT_EQ(run(cubeProbe, cube + (dir / "cu_%d.png").string()).exitCode, 0);
    Result<Image8> ct = readPng(dir / "ct_2.png");
    Result<Image8> cu = readPng(dir / "cu_2.png");
    ASSERT_TRUE(ct.ok() && cu.ok());
    EXPECT_TRUE(ct->rgba == cu->rgba);
    // Tiles that do not divide the canvas, with supersampling and motion blur, as EXR floats.
    const std::string sampled = "--size 300x170 --supersample 2 --motion-blur 2 --frames 2 --out ";
    ASSERT_EQ(run(kSampling, sampled + (dir / "t_%d.exr").string() + " --tile 64").exitCode, 0);
    ASSERT_EQ(run(kSampling, sampled + (dir / "w_%d.exr").string()).exitCode, 0);
    Result<ImageF32> ta = readExr(dir / "t_1.exr");
    Result<ImageF32> wa = readExr(dir / "w_1.exr");
    ASSERT_TRUE(ta.ok() && wa.ok());
    EXPECT_TRUE(ta->rgba == wa->rgba);
}

// Issue 44: GPUs shade 2x2 quads from the target's corner, and dFdx/dFdy difference the pixels of
// a quad. A tile whose origin is odd in the canvas paired other pixels than the untiled render
// (odd heights and odd --tile: every row quad flipped). A quad-parity probe and a smooth field's
// derivatives, at odd sizes and tiles: tiled equals untiled byte for byte.
TEST(TiledStill, TilesKeepTheCanvasDerivativeQuadsAtOddSizesAndTiles) {
    const fs::path dir = freshOutputDir("tiled-still-quads");
    writeFile(dir / "toy/manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "toy/image.glsl",
              "void mainImage(out vec4 c, in vec2 p) {\n"
              "    vec2 parity = vec2(dFdx(mod(p.x, 2.0)), dFdy(mod(p.y, 2.0)));  // +1 or -1 by quad\n"
              "    float f = sin(p.x * p.y * 0.013) * 40.0;\n"
              "    c = vec4(0.5 + 0.5 * parity, 0.5 + 0.5 * dFdx(f) + 0.25 * dFdy(f), 1.0);\n}\n");
    struct Case {
        const char* size;
        const char* tile;
    };
    for (const Case& c : {Case{"161x91", "33"}, Case{"160x91", "32"}, Case{"161x90", "33"}, Case{"97x41", "16"}}) {
        const std::string name = std::string(c.size) + "_" + c.tile;
        const CommandResult tiled = run(dir / "toy", std::string("--size ") + c.size + " --tile " + c.tile + " --out " +
                                                         (dir / (name + "_tiled.png")).string());
        ASSERT_EQ(tiled.exitCode, 0) << tiled.output;
        const CommandResult whole =
            run(dir / "toy", std::string("--size ") + c.size + " --out " + (dir / (name + "_whole.png")).string());
        ASSERT_EQ(whole.exitCode, 0) << whole.output;
        Result<Image8> a = readPng(dir / (name + "_tiled.png"));
        Result<Image8> b = readPng(dir / (name + "_whole.png"));
        ASSERT_TRUE(a.ok() && b.ok());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < a->rgba.size(); i += 4)
            differing += !std::equal(a->rgba.begin() + static_cast<std::ptrdiff_t>(i),
                                     a->rgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                                     b->rgba.begin() + static_cast<std::ptrdiff_t>(i));
        EXPECT_EQ(differing, 0u) << c.size << " --tile " << c.tile << ": pixels differ";
    }
}

// The rows of a PNG, read one at a time (the whole image is 900 MB): `keep` gets the rows asked.
std::map<int, std::vector<std::uint8_t>> pngRows(const fs::path& path, const std::vector<int>& keep, int& width,
                                                 int& height) {
    std::map<int, std::vector<std::uint8_t>> rows;
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return rows;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        std::fclose(file);
        return {};
    }
    png_init_io(png, file);
    png_read_info(png, info);
    width = static_cast<int>(png_get_image_width(png, info));
    height = static_cast<int>(png_get_image_height(png, info));
    std::vector<std::uint8_t> row(png_get_rowbytes(png, info));
    for (int y = 0; y < height; ++y) {
        png_read_row(png, row.data(), nullptr);
        if (std::find(keep.begin(), keep.end(), y) != keep.end()) rows[y] = row;
    }
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(file);
    return rows;
}

TEST(TiledStill, A20000x11250StillHasTheExpectedCornersAndCentreInUnder1GB) {
    constexpr int W = 20000, H = 11250;
    const fs::path dir = freshOutputDir("tiled-still-large");
    const CommandResult made = run(kProbe, "--size 20000x11250 --out " + (dir / "still.png").string());
    ASSERT_EQ(made.exitCode, 0) << made.output;
    EXPECT_NE(made.output.find("1 frame at 20000x11250"), std::string::npos) << made.output;
    // The largest child this test process waited for (the shell waited for toyhost).
    rusage usage{};
    ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &usage), 0);
    EXPECT_LT(usage.ru_maxrss, 1024L * 1024) << "peak memory " << usage.ru_maxrss / 1024 << " MiB";

    int width = 0, height = 0;
    const int centre = H / 2;
    const auto rows = pngRows(dir / "still.png", {0, centre, H - 1}, width, height);
    ASSERT_EQ(width, W);
    ASSERT_EQ(height, H);
    ASSERT_EQ(rows.size(), 3u);
    // PNG row r is GL row H - 1 - r; the value is round((p + 0.5) / size * 255).
    auto expected = [](int p, int size) { return static_cast<int>(std::lround((p + 0.5) / size * 255.0)); };
    for (const auto& [row, pixels] : rows)
        for (int x : {0, W / 2, W - 1}) {
            const int y = H - 1 - row;
            EXPECT_EQ(pixels[static_cast<std::size_t>(x) * 4 + 0], expected(x, W)) << "x " << x << ", row " << row;
            EXPECT_EQ(pixels[static_cast<std::size_t>(x) * 4 + 1], expected(y, H)) << "x " << x << ", row " << row;
            EXPECT_EQ(pixels[static_cast<std::size_t>(x) * 4 + 2], 0);
            EXPECT_EQ(pixels[static_cast<std::size_t>(x) * 4 + 3], 255);
        }
}

TEST(TiledStill, WhatCannotBeTiledIsRefusedSayingWhy) {
    const fs::path lakes = sourceDir() / "shadertoys/ripple-pool";  // has buffers
    CommandResult big = run(lakes, "--size 20000x11250");
    EXPECT_EQ(big.exitCode, 2) << big.output;
    EXPECT_NE(big.output.find("buffer is the size of the whole canvas"), std::string::npos) << big.output;
    EXPECT_NE(big.output.find("--size"), std::string::npos) << big.output;
    CommandResult tiled = run(lakes, "--size 320x180 --tile 64");
    EXPECT_EQ(tiled.exitCode, 2) << tiled.output;
    EXPECT_NE(tiled.output.find("--tile"), std::string::npos) << tiled.output;
    CommandResult video = run(kProbe, "--size 20000x100 --out " + (testOutputDir() / "tiled.mp4").string());
    EXPECT_EQ(video.exitCode, 2) << video.output;
    EXPECT_NE(video.output.find("PNG or EXR"), std::string::npos) << video.output;
    CommandResult tiny = run(kProbe, "--size 64x64 --tile 8");
    EXPECT_EQ(tiny.exitCode, 2) << tiny.output;
    CommandResult huge = run(kProbe, "--size 70000x100");
    EXPECT_EQ(huge.exitCode, 2) << huge.output;
    EXPECT_NE(huge.output.find("65536x65536"), std::string::npos) << huge.output;
}

}  // namespace
}  // namespace toyhost::testing
