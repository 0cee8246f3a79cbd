// toyhost against the floor: tools/bench/floor_render renders an Image pass with its own,
// hand-written EGL + GLES code and none of the runtime library, so agreement between the two
// checks toyhost's header, uniforms, render target and PNG capture independently.
#include "GlTestSupport.h"
#include "ImageCompare.h"

#include <cmath>
#include <cstdio>

#include "image/ImageWriters.h"
#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

// Runs floor_render with `arguments` (already shell-quoted), stdout and stderr together.
CommandResult runFloor(const std::string& arguments) { return runCommand(TOYHOST_FLOOR_BIN, arguments); }

// Writes an image (rows bottom first, like every image in memory) as PNG.
void writeImagePng(const std::filesystem::path& path, const Image8& image) {
    const Status written = writePng(path, image.width, image.height, image.rgba);
    EXPECT_TRUE(written.ok()) << written.error().text();
}

TEST(FloorMatch, OceanRendersLikeTheIndependentFloorProgram) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/image.glsl");
    const std::filesystem::path dir = freshOutputDir("floor-match");
    const std::filesystem::path toyhostPng = dir / "toyhost.png";
    const std::filesystem::path floorPng = dir / "floor.png";

    const CommandResult toyhost =
        runToyhost("run " + quoted(sourceDir() / "shadertoys/ocean") +
                   " --size 320x180 --frames 1 --start-time 3 --quiet --out " + quoted(toyhostPng));
    ASSERT_EQ(toyhost.exitCode, 0) << toyhost.output;
    const CommandResult floor =
        runFloor(quoted(sharedDir() / "shadertoys/MdXyzX/image.glsl") +
                 " --size 320x180 --time 3 --out " + quoted(floorPng));
    ASSERT_EQ(floor.exitCode, 0) << floor.output;

    auto actual = loadImageFile(toyhostPng);
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    auto expected = loadImageFile(floorPng);
    ASSERT_TRUE(expected.ok()) << expected.error().text();
    ASSERT_EQ(actual->width, 320);
    ASSERT_EQ(actual->height, 180);
    ASSERT_TRUE(sameSize(*actual, *expected));

    const double psnr = psnrRgb(*actual, *expected);
    if (std::isinf(psnr)) {
        std::printf("floor match: identical\n");
        return;
    }
    std::printf("floor match: PSNR %.2f dB, mean abs error %.4f, max abs error %d\n", psnr,
                meanAbsError(*actual, *expected), maxAbsError(*actual, *expected));
    EXPECT_GE(psnr, 40.0) << "toyhost and floor_render disagree; see " << dir;
    if (!(psnr >= 40.0)) writeImagePng(dir / "diff.png", makeDiffImage(*actual, *expected, 8));
}

}  // namespace
}  // namespace toyhost::testing
