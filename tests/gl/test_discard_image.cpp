// An Image that discards shows what the previous frame drew there, as the site's preserved canvas
// does (issue 30, webref probe discard_image): frames that are not captured still draw such an
// Image, so `--capture-every 3` gives the same frame 3 as `--capture-every 1`.
#include "GlTestSupport.h"

#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

TEST(DiscardImage, FramesNotCapturedStillLeaveWhatTheyDrew) {
    const fs::path dir = freshOutputDir("gl/discard-image");
    writeFile(dir / "toy" / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    // From frame 2 on, the left half keeps frame 1's colour (R = 1/16).
    writeFile(dir / "toy" / "image.glsl",
              "void mainImage(out vec4 o, in vec2 fc) {\n"
              "  o = vec4(float(iFrame) / 16.0, 0.5, 0.25, 1.0);\n"
              "  if (fc.x < 8.0 && iFrame > 1) discard;\n}\n");
    for (int every : {1, 3}) {
        const fs::path out = dir / ("every" + std::to_string(every));
        auto run = runToyhost("run " + quoted(dir / "toy") + " --size 16x4 --frames 7 --capture-every " +
                              std::to_string(every) + " --quiet --sync-capture --out " + quoted(out / "f_%02d.png"));
        ASSERT_EQ(run.exitCode, 0) << run.output;
    }
    for (const char* name : {"f_03.png", "f_06.png"}) {
        SCOPED_TRACE(name);
        auto each = loadImageFile(dir / "every1" / name);
        auto sparse = loadImageFile(dir / "every3" / name);
        ASSERT_TRUE(each.ok() && sparse.ok());
        EXPECT_EQ(each->rgba, sparse->rgba);
        EXPECT_EQ(sparse->rgba[0], 16);  // frame 1's colour, on the left
    }
    auto third = loadImageFile(dir / "every3" / "f_03.png");
    ASSERT_TRUE(third.ok());
    EXPECT_EQ(third->rgba[12 * 4], 48);  // frame 3's own, on the right
}

}  // namespace
}  // namespace toyhost::testing
