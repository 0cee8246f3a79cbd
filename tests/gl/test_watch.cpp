// Headless --watch: the frames are rendered again when a file of the shadertoy changes; a pass
// that stops compiling is reported with file:line and the last good frames stay; Ctrl-C ends.
#include "GlTestSupport.h"

#include <csignal>
#include <fstream>

#include "Processes.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::array<int, 3> column5(const fs::path& png) {
    Result<Image8> image = readPng(png);
    if (!image) return {-1, -1, -1};
    return {image->rgba[20], image->rgba[21], image->rgba[22]};
}

void replaceIn(const fs::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find(from), from.size(), to);
    std::ofstream(file) << text;
}

TEST(Watch, ChangedFilesRenderAgainAndErrorsKeepTheLastGoodFrames) {
    const fs::path dir = freshOutputDir("watch");
    for (const char* file : {"manifest.json", "buffer_a.glsl", "image.glsl"})
        fs::copy_file(sourceDir() / "shadertoys/window-probe" / file, dir / file);
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    BackgroundProcess toyhost(toyhostBinary(),
                              {"run", dir.string(), "--headless", "--watch", "--size", "32x16", "--frames", "2",
                               "--quiet", "--out", (dir / "out_%d.png").string()},
                              dir / "toyhost.log");
    ASSERT_TRUE(toyhost.waitForLog("watching", 30)) << toyhost.log();
    EXPECT_EQ(column5(dir / "out_1.png"), (std::array<int, 3>{10, 20, 30}));

    replaceIn(dir / "image.glsl", "vec4(10, 20, 30, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost.waitForLog("watching", 30, 2)) << toyhost.log();
    EXPECT_EQ(column5(dir / "out_1.png"), (std::array<int, 3>{40, 50, 60}));

    replaceIn(dir / "image.glsl", "vec4(40, 50, 60, 255)", "vec4(40, 50, nothing_here, 255)");
    ASSERT_TRUE(toyhost.waitForLog("watching", 30, 3)) << toyhost.log();
    EXPECT_NE(toyhost.log().find((dir / "image.glsl").string() + ":21:"), std::string::npos) << toyhost.log();
    EXPECT_EQ(column5(dir / "out_1.png"), (std::array<int, 3>{40, 50, 60})) << "the last good frames stay";
    EXPECT_TRUE(toyhost.running()) << "a compile error does not end a --watch run";

    toyhost.signal(SIGINT);
    EXPECT_EQ(toyhost.wait(10), 0) << toyhost.log();
}

}  // namespace
}  // namespace toyhost::testing
