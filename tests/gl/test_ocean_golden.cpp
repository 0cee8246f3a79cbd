// afl_ext's ocean (MdXyzX), verbatim from ../shared, against checked-in golden frames at
// 320x180, with the tolerance of Golden.h (a frame 0.05 s off scores about 20 dB). On failure the
// actual frame and an 8x diff are written to <build>/test-output/golden/. Refresh on purpose with
// TOYHOST_UPDATE_GOLDENS=1.
#include "GlTestSupport.h"
#include "Golden.h"

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
    expectMatchesGolden(sourceDir(), std::string(c.name) + ".png", actualPath);
}

INSTANTIATE_TEST_SUITE_P(Frames, OceanGolden,
                         ::testing::Values(GoldenCase{"ocean_t0", "0"}, GoldenCase{"ocean_t4", "4"},
                                           GoldenCase{"ocean_t9_5", "9.5"}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace toyhost::testing
