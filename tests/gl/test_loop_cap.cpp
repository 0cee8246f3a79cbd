// llvmpipe ends a pixel's loops after 65535 iterations in all (Mesa's gallivm
// LP_MAX_TGSI_LOOP_ITERATIONS, a compile-time constant: no environment variable or driconf option
// lifts it), where the browser runs every iteration (issue 42). A run says so with a warning,
// "llvmpipe's loop cap", at each loop whose constant bounds pass it (shader/LoopCap.h).
#include "GlTestSupport.h"

#include <toyhost/Session.h>

#include <vector>

namespace toyhost::testing {
namespace {

// Counts its iterations in a float (exact up to 2^24) and shows the count's three bytes.
const char* const kHundredThousand =
    "void mainImage(out vec4 o, in vec2 f) {\n"
    "    float n = 0.0;\n"
    "    for (int i = 0; i < 100000; i++) n += 1.0;\n"
    "    o = vec4(mod(n, 256.0), mod(floor(n / 256.0), 256.0), floor(n / 65536.0), 255.0) / 255.0;\n"
    "}\n";

TEST(LoopCapGl, AHundredThousandIterationsWarnAndLlvmpipeCounts65535) {
    const std::filesystem::path dir = freshOutputDir("gl/loop-cap");
    writeFile(dir / "toy" / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "toy" / "image.glsl", kHundredThousand);
    const CommandResult run = runToyhost("run '" + (dir / "toy").string() + "' --size 4x4 --frames 1 --out '" +
                                         (dir / "f_%d.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find((dir / "toy" / "image.glsl").string() + ":3: warning: Image: llvmpipe's loop cap: this "
                                                                      "loop runs 100000 iterations per pixel"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("the site runs them all"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("[shader.loop-cap]"), std::string::npos) << run.output;

    // The warning's premise: llvmpipe stops the loop at 65535 (0x00FFFF); the browser counts
    // 100000 (0x0186A0). Should a Mesa lift the limit, this fails and the warning must go.
    const std::vector<std::uint8_t> pixels = renderImageOnce(dir / "pixels", kHundredThousand);
    ASSERT_EQ(pixels.size(), 64u);
    EXPECT_EQ(pixels[0], 0xFF);
    EXPECT_EQ(pixels[1], 0xFF);
    EXPECT_EQ(pixels[2], 0x00);
}

TEST(LoopCapGl, ALoopWithinTheLimitSaysNothing) {
    const std::filesystem::path dir = freshOutputDir("gl/loop-cap-within");
    writeFile(dir / "toy" / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "toy" / "image.glsl",
              "void mainImage(out vec4 o, in vec2 f) { float n = 0.0; for (int i = 0; i < 60000; i++) n += 1.0;\n"
              "    o = vec4(n / 65535.0); }\n");
    const CommandResult run = runToyhost("run '" + (dir / "toy").string() + "' --size 4x4 --frames 1 --out '" +
                                         (dir / "f_%d.png").string() + "'");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(run.output.find("loop cap"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace toyhost::testing
