// afl_ext's ocean (MdXyzX), verbatim from ../shared, against checked-in golden frames at
// 320x180. Tolerance: PSNR >= 40 dB over RGB and mean absolute error <= 1 level (llvmpipe is
// deterministic on one machine; the margin absorbs LLVM code generation differences between
// CPUs, such as fused multiply-adds, which move a few wave-crest pixels. A frame 0.05 s off
// scores about 20 dB). On failure the actual frame and an 8x diff are written to
// <build>/test-output/golden/. Refresh on purpose with TOYHOST_UPDATE_GOLDENS=1.
#include "GlTestSupport.h"
#include "ImageCompare.h"

#include "image/ImageWriters.h"
#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

struct GoldenCase {
    const char* name;
    const char* startTime;
    friend void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }
};

class OceanGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(OceanGolden, MatchesCheckedInFrame) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/image.glsl");
    const GoldenCase& c = GetParam();
    const fs::path dir = freshOutputDir(std::string("golden/") + c.name);
    const fs::path actualPath = dir / (std::string(c.name) + ".actual.png");
    auto run = runToyhost("run '" + (sourceDir() / "shadertoys/ocean").string() +
                          "' --size 320x180 --frames 1 --start-time " + c.startTime + " --quiet --out '" +
                          actualPath.string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const fs::path golden = sourceDir() / "tests/golden" / (std::string(c.name) + ".png");
    if (const char* update = std::getenv("TOYHOST_UPDATE_GOLDENS"); update && std::string(update) == "1") {
        fs::copy_file(actualPath, golden, fs::copy_options::overwrite_existing);
        GTEST_SKIP() << "golden refreshed: " << golden;
    }
    auto expected = loadImageFile(golden);
    ASSERT_TRUE(expected.ok()) << expected.error().text() << " (refresh with TOYHOST_UPDATE_GOLDENS=1)";
    auto actual = loadImageFile(actualPath);
    ASSERT_TRUE(actual.ok()) << actual.error().text();
    ASSERT_TRUE(sameSize(*expected, *actual));

    const double psnr = psnrRgb(*expected, *actual);
    const double mae = meanAbsError(*expected, *actual);
    std::printf("%s: PSNR %.2f dB, mean abs error %.4f, max %d\n", c.name, psnr, mae, maxAbsError(*expected, *actual));
    if (psnr < 40.0 || mae > 1.0) {
        Image8 diff = makeDiffImage(*expected, *actual, 8);
        (void)writePng(dir / (std::string(c.name) + ".diff.png"), diff.width, diff.height, diff.rgba);
        fs::copy_file(golden, dir / (std::string(c.name) + ".expected.png"), fs::copy_options::overwrite_existing);
        ADD_FAILURE() << c.name << ": PSNR " << psnr << " dB (need >= 40), mean abs error " << mae
                      << " (need <= 1); actual, expected and diff are in " << dir;
    }
}

INSTANTIATE_TEST_SUITE_P(Frames, OceanGolden,
                         ::testing::Values(GoldenCase{"ocean_t0", "0"}, GoldenCase{"ocean_t4", "4"},
                                           GoldenCase{"ocean_t9_5", "9.5"}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace toyhost::testing
