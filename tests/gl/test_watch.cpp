// Headless --watch with real files changing under the running process: the frames are rendered
// again after every change and toyhost says which file changed and what it rendered; a pass that
// stops compiling is reported with file:line, no frames are written and the last good frames
// stay; undoing the mistake renders again with the error gone; a texture rewritten in place is
// applied (as in a window: the same reload rule); Ctrl-C ends the run (0), SIGTERM interrupts it
// (143).
#include "GlTestSupport.h"

#include <algorithm>
#include <csignal>
#include <fstream>

#include "Processes.h"
#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::array<int, 3> column(const fs::path& png, int x) {
    Result<Image8> image = readPng(png);
    if (!image) return {-1, -1, -1};
    const std::size_t at = static_cast<std::size_t>(x) * 4;
    return {image->rgba[at], image->rgba[at + 1], image->rgba[at + 2]};
}

void replaceIn(const fs::path& file, const std::string& from, const std::string& to) {
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find(from), from.size(), to);
    std::ofstream(file) << text;
}

class Watch : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = freshOutputDir(std::string("watch/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        for (const char* file : {"manifest.json", "buffer_a.glsl", "image.glsl", "probe.png"})
            fs::copy_file(sourceDir() / "shadertoys/window-probe" / file, dir_ / file);
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        toyhost_.emplace(toyhostBinary(),
                         std::vector<std::string>{"run", dir_.string(), "--headless", "--watch", "--size", "32x16",
                                                  "--frames", "2", "--out", (dir_ / "out_%d.png").string()},
                         dir_ / "toyhost.log");
        ASSERT_TRUE(toyhost_->waitForLog("watching", 30)) << toyhost_->log();
    }
    fs::path dir_;
    std::optional<BackgroundProcess> toyhost_;
};

TEST_F(Watch, ChangedFilesRenderAgainErrorsKeepTheLastGoodFramesAndUndoClearsThem) {
    EXPECT_EQ(column(dir_ / "out_1.png", 5), (std::array<int, 3>{10, 20, 30}));

    replaceIn(dir_ / "image.glsl", "vec4(10, 20, 30, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("watching", 30, 2)) << toyhost_->log();
    // Issue 27: a round where nothing fails takes two lines (what changed and what it rendered),
    // and a --watch round restarts at frame 0, so nothing says that buffers keep their content.
    {
        const std::string log = toyhost_->log();
        const std::size_t notice = log.find("toyhost: notice: image.glsl changed: recompiled Image; rendering 2 frames again from frame 0");
        ASSERT_NE(notice, std::string::npos) << log;
        const std::size_t watching = log.find("watching", notice);
        ASSERT_NE(watching, std::string::npos) << log;
        EXPECT_EQ(std::count(log.begin() + static_cast<std::ptrdiff_t>(notice), log.begin() + static_cast<std::ptrdiff_t>(watching), '\n'), 1)
            << log.substr(notice);
        EXPECT_EQ(log.find("keep their content"), std::string::npos) << log;
    }
    EXPECT_EQ(column(dir_ / "out_1.png", 5), (std::array<int, 3>{40, 50, 60}));

    replaceIn(dir_ / "image.glsl", "vec4(40, 50, 60, 255)", "vec4(40, 50, nothing_here, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("watching", 30, 3)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find((dir_ / "image.glsl").string() + ":22:"), std::string::npos) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("no frames written"), std::string::npos) << toyhost_->log();
    {
        // Each compile error once (it was printed by the reload and again by the round).
        const std::string log = toyhost_->log();
        std::size_t errors = 0;
        for (std::size_t at = log.find("`nothing_here' undeclared"); at != std::string::npos;
             at = log.find("`nothing_here' undeclared", at + 1))
            ++errors;
        EXPECT_EQ(errors, 1u) << log;
    }
    EXPECT_EQ(column(dir_ / "out_1.png", 5), (std::array<int, 3>{40, 50, 60})) << "the last good frames stay";
    EXPECT_TRUE(toyhost_->running()) << "a compile error does not end a --watch run";

    // Undo: exactly the text that runs; nothing to recompile, and the frames are written again.
    const std::size_t writtenBefore = [&] {
        std::size_t n = 0;
        const std::string log = toyhost_->log();
        for (std::size_t at = log.find("wrote 2 files"); at != std::string::npos; at = log.find("wrote 2 files", at + 1)) ++n;
        return n;
    }();
    replaceIn(dir_ / "image.glsl", "vec4(40, 50, nothing_here, 255)", "vec4(40, 50, 60, 255)");
    ASSERT_TRUE(toyhost_->waitForLog("wrote 2 files", 30, writtenBefore + 1)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("nothing to recompile"), std::string::npos) << toyhost_->log();

    toyhost_->signal(SIGINT);
    EXPECT_EQ(toyhost_->wait(10), 0) << "Ctrl-C ends a --watch run\n" << toyhost_->log();
}

TEST_F(Watch, ATextureRewrittenInPlaceIsAppliedAndSigtermInterrupts) {
    EXPECT_EQ(column(dir_ / "out_1.png", 6), (std::array<int, 3>{100, 150, 200}));
    const std::vector<std::uint8_t> pixel = {30, 60, 90, 255};
    ASSERT_TRUE(writePng(dir_ / "probe.png", 1, 1, pixel).ok());
    ASSERT_TRUE(toyhost_->waitForLog("watching", 30, 2)) << toyhost_->log();
    EXPECT_NE(toyhost_->log().find("probe.png changed: new structure"), std::string::npos) << toyhost_->log();
    EXPECT_EQ(column(dir_ / "out_1.png", 6), (std::array<int, 3>{30, 60, 90}));

    toyhost_->signal(SIGTERM);
    EXPECT_EQ(toyhost_->wait(10), 143) << toyhost_->log();
}

}  // namespace
}  // namespace toyhost::testing
