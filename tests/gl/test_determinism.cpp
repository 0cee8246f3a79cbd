// The same run twice gives identical bytes: PNG frames of both originals and a float EXR dump of
// a simulation buffer.
#include "GlTestSupport.h"

#include <fstream>
#include <iterator>

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

void expectSameFiles(const fs::path& a, const fs::path& b, int expectedCount) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(a)) {
        const fs::path twin = b / entry.path().filename();
        ASSERT_TRUE(fs::exists(twin)) << twin;
        const std::string left = bytesOf(entry.path());
        EXPECT_FALSE(left.empty()) << entry.path();
        EXPECT_TRUE(left == bytesOf(twin)) << entry.path() << " differs from " << twin;
        ++count;
    }
    EXPECT_EQ(count, expectedCount);
}

TEST(Determinism, MountainsLakesFramesAndBufferDumpRepeatExactly) {
    TOYHOST_REQUIRE_SHARED("shadertoys/7tSSDD/image.glsl");
    const fs::path dir = freshOutputDir("determinism-ml");
    const std::string base = "run '" + (sourceDir() / "shadertoys/mountains-lakes").string() +
                             "' --size 160x128 --frames 24 --capture-every 8 --date 2026-11-21T12:00:00 --quiet";
    for (const char* run : {"a", "b"}) {
        auto png = runToyhost(base + " --out '" + (dir / run / "image_%03d.png").string() + "'");
        ASSERT_EQ(png.exitCode, 0) << png.output;
        auto exr = runToyhost(base + " --capture-pass 'Buffer C' --out '" + (dir / run / "c_%03d.exr").string() + "'");
        ASSERT_EQ(exr.exitCode, 0) << exr.output;
    }
    expectSameFiles(dir / "a", dir / "b", 8);  // frames 0, 8, 16, 23 as PNG and EXR
}

TEST(Determinism, OceanFramesRepeatExactly) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/image.glsl");
    const fs::path dir = freshOutputDir("determinism-ocean");
    for (const char* run : {"a", "b"}) {
        auto result = runToyhost("run '" + (sourceDir() / "shadertoys/ocean").string() +
                                 "' --size 160x90 --frames 2 --start-time 2 --quiet --out '" +
                                 (dir / run / "ocean_%d.png").string() + "'");
        ASSERT_EQ(result.exitCode, 0) << result.output;
    }
    expectSameFiles(dir / "a", dir / "b", 2);
}

}  // namespace
}  // namespace toyhost::testing
