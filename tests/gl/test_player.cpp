// The Player, the engine every driver runs: its own frame counter (restart, rewinds of time),
// all-or-nothing resize, hot reload that keeps the last good program and the buffers, a repaint of
// the last frame (a paused window after an edit), shader errors that name the user's file and
// line, and EGL contexts that do not disturb each other.
#include "EglDevicePlatform.h"
#include "GlTestSupport.h"

#include <fstream>

#include "core/Diagnostic.h"
#include "manifest/ManifestLoader.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// The Player itself, below the SessionCore: planned as real runs plan it, with an allocator tests can
// make fail.
std::unique_ptr<Player> loadPlayer(const std::shared_ptr<GlContext>& context, const fs::path& target, int width,
                                   int height, bool floatImage = false, TextureAllocator allocate = {}) {
    auto manifest = loadShadertoy(target);
    EXPECT_TRUE(manifest.ok()) << manifest.error().text();
    if (!manifest.ok()) return nullptr;
    auto plan = planPlayer(std::move(*manifest), MediaOptions{});
    EXPECT_TRUE(plan.ok()) << plan.error().text();
    if (!plan.ok()) return nullptr;
    PlayerDesc desc;
    desc.width = width;
    desc.height = height;
    desc.floatImage = floatImage;
    desc.allocate = std::move(allocate);
    auto player = Player::create(context, std::move(*plan), desc);
    EXPECT_TRUE(player.ok()) << player.error().text();
    if (!player.ok()) return nullptr;
    return std::move(*player);
}

void stepAt(Player& player, std::span<const InputEvent> events = {}) {
    player.step(fixedStep(player.frame()), events);
}

// Buffer A adds `increment` to its previous value every frame (red), and writes iFrame (green).
std::string counterCode(const std::string& increment) {
    return "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
           "    vec4 previous = texelFetch(iChannel0, ivec2(fragCoord), 0);\n"
           "    fragColor = vec4(previous.r + " + increment + ", float(iFrame), fragCoord);\n"
           "}\n";
}

const char* kImageCode =
    "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
    "    fragColor = texelFetch(iChannel0, ivec2(fragCoord), 0) / 16.0;\n"
    "}\n";

const char* kCounterManifest = R"({
  "name": "counter",
  "passes": {
    "Buffer A": { "source": "buffer_a.glsl", "channels": { "iChannel0": { "buffer": "A" } } },
    "Image": { "source": "image.glsl", "channels": { "iChannel0": { "buffer": "A" } } }
  }
})";

// The same, with a Buffer B that reads A: another pass graph.
const char* kTwoBufferManifest = R"({
  "name": "counter",
  "passes": {
    "Buffer A": { "source": "buffer_a.glsl", "channels": { "iChannel0": { "buffer": "A" } } },
    "Buffer B": { "source": "image.glsl", "channels": { "iChannel0": { "buffer": "A" } } },
    "Image": { "source": "image.glsl", "channels": { "iChannel0": { "buffer": "B" } } }
  }
})";


class PlayerTest : public GlTest {
protected:
    static constexpr int kW = 8, kH = 4;
    void SetUp() override {
        dir_ = freshOutputDir(std::string("player/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        writeFile(dir_ / "manifest.json", kCounterManifest);
        writeFile(dir_ / "buffer_a.glsl", counterCode("1.0"));
        writeFile(dir_ / "image.glsl", kImageCode);
    }
    Result<PlayerPlan> plan() const {
        auto manifest = loadManifest(dir_);
        if (!manifest) return manifest.error();
        return planPlayer(std::move(*manifest), MediaOptions{});
    }
    std::unique_ptr<Player> player(TextureAllocator allocate = {}) {
        return loadPlayer(context_, dir_, kW, kH, /*floatImage=*/false, std::move(allocate));
    }
    // Buffer A's texel (x, y): (count, iFrame, x + 0.5, y + 0.5).
    static std::array<float, 4> texel(const Player& p, int x, int y) {
        std::vector<float> rgba;
        p.readRgba32f(PassId::BufferA, rgba);
        const std::size_t at = 4 * (static_cast<std::size_t>(y) * p.width() + x);
        return {rgba[at], rgba[at + 1], rgba[at + 2], rgba[at + 3]};
    }
    fs::path dir_;
};

TEST_F(PlayerTest, RestartGoesBackToFrameZeroWithClearedBuffers) {
    auto p = player();
    ASSERT_TRUE(p);
    for (int i = 0; i < 3; ++i) stepAt(*p);
    EXPECT_EQ(p->frame(), 3);
    EXPECT_EQ(texel(*p, 0, 0)[0], 3.0f);
    EXPECT_EQ(texel(*p, 0, 0)[1], 2.0f);
    p->restart();
    EXPECT_EQ(p->frame(), 0);
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 1.0f) << "the buffer was cleared: counting starts again";
    EXPECT_EQ(texel(*p, 0, 0)[1], 0.0f) << "iFrame 0";
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 2.0f) << "after a restart at an odd step, the previous frame is still read";
    EXPECT_EQ(texel(*p, 0, 0)[1], 1.0f);
}

TEST_F(PlayerTest, RewindingTimeNeverReadsAStaleFrame) {
    auto p = player();
    ASSERT_TRUE(p);
    for (double t : {2.0, 1.0, 0.0, 5.0, 0.5}) p->step(FrameTime{t, 1.0 / 60.0, 60.0, glm::vec4(0)});
    EXPECT_EQ(texel(*p, 3, 1)[0], 5.0f);
    EXPECT_EQ(texel(*p, 3, 1)[1], 4.0f);
}

TEST_F(PlayerTest, ResizeKeepsContentBottomLeftAndIFrameGoesOn) {
    auto p = player();
    ASSERT_TRUE(p);
    for (int i = 0; i < 2; ++i) stepAt(*p);
    ASSERT_TRUE(p->resize(12, 6).ok());
    EXPECT_EQ(p->width(), 12);
    EXPECT_EQ(p->height(), 6);
    stepAt(*p);
    EXPECT_EQ(texel(*p, 7, 3)[0], 3.0f) << "an old texel kept its count";
    EXPECT_EQ(texel(*p, 11, 5)[0], 1.0f) << "a new texel starts from zero";
    EXPECT_EQ(texel(*p, 11, 5)[1], 2.0f) << "iFrame went on";
}

TEST_F(PlayerTest, AResizeThatFailsHalfwayLeavesTheOldSizeAndContent) {
    int calls = 0;
    int failAt = -1;  // the allocation (counted from 1) that fails; -1: none
    auto p = player([&](int w, int h, GLenum format, bool mipmapped) -> Result<RenderTexture> {
        if (++calls == failAt) return Error("injected allocation failure", Code::GlTexture);
        return createRenderTexture(w, h, format, mipmapped);
    });
    ASSERT_TRUE(p);
    for (int i = 0; i < 2; ++i) stepAt(*p);
    const int perResize = [&] {
        const int before = calls;
        EXPECT_TRUE(p->resize(kW, kH + 1).ok());
        EXPECT_TRUE(p->resize(kW, kH).ok());
        return (calls - before) / 2;
    }();
    ASSERT_GE(perResize, 3) << "Buffer A's two slots and the Image target";
    for (int failing = 1; failing <= perResize; ++failing) {
        SCOPED_TRACE("allocation " + std::to_string(failing) + " of the resize fails");
        failAt = calls + failing;
        Status resized = p->resize(20, 10);
        EXPECT_FALSE(resized.ok());
        EXPECT_EQ(p->width(), kW);
        EXPECT_EQ(p->height(), kH);
        EXPECT_EQ(texel(*p, 7, 3)[0], 2.0f) << "content intact";
    }
    failAt = -1;
    stepAt(*p);
    EXPECT_EQ(texel(*p, 7, 3)[0], 3.0f) << "the player goes on as if nothing happened";
    EXPECT_FALSE(p->resize(1 << 20, 4).ok()) << "larger than GL allows: refused before any allocation";
}

TEST_F(PlayerTest, ReloadKeepsTheLastGoodProgramAndTheBuffers) {
    auto p = player();
    ASSERT_TRUE(p);
    for (int i = 0; i < 2; ++i) stepAt(*p);

    writeFile(dir_ / "buffer_a.glsl", counterCode("undefined_thing"));
    auto broken = plan();
    ASSERT_TRUE(broken.ok()) << broken.error().text();
    ReloadReport report = p->reload(std::move(*broken));
    EXPECT_FALSE(report.structureChanged);
    EXPECT_FALSE(report.applied);
    ASSERT_FALSE(report.problems.empty());
    EXPECT_EQ(report.problems[0].file, (dir_ / "buffer_a.glsl").string());
    EXPECT_EQ(report.problems[0].line, 3);
    EXPECT_EQ(report.problems[0].pass, "Buffer A");
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 3.0f) << "the old program still runs";

    writeFile(dir_ / "buffer_a.glsl", counterCode("10.0"));
    auto fixed = plan();
    ASSERT_TRUE(fixed.ok());
    report = p->reload(std::move(*fixed));
    EXPECT_TRUE(report.applied);
    EXPECT_TRUE(report.problems.empty());
    EXPECT_EQ(report.recompiled, std::vector<std::string>{"Buffer A"}) << "Image did not change";
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 13.0f) << "new code, buffer content and iFrame kept";
    EXPECT_EQ(texel(*p, 0, 0)[1], 3.0f);
}

// A paused window after a reload: the last frame again with the new code, at its own iFrame;
// Buffer A reads its own last output, so it takes one more step.
TEST_F(PlayerTest, ARepaintRendersTheLastFrameAgainWithTheNewCode) {
    auto p = player();
    ASSERT_TRUE(p);
    EXPECT_FALSE(p->repaint(fixedStep(0))) << "no frame rendered yet";
    EXPECT_EQ(p->frame(), 0);
    for (int i = 0; i < 3; ++i) stepAt(*p);
    writeFile(dir_ / "buffer_a.glsl", counterCode("10.0"));
    auto next = plan();
    ASSERT_TRUE(next.ok()) << next.error().text();
    ASSERT_TRUE(p->reload(std::move(*next)).applied);
    ASSERT_TRUE(p->repaint(fixedStep(2)));
    EXPECT_EQ(p->frame(), 3) << "the next frame is still frame 3";
    EXPECT_EQ(texel(*p, 0, 0)[0], 13.0f) << "the new code ran on the last frame's output";
    EXPECT_EQ(texel(*p, 0, 0)[1], 2.0f) << "at the shown frame's iFrame";
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 23.0f) << "the next frame reads the repainted one";
    EXPECT_EQ(texel(*p, 0, 0)[1], 3.0f);
    p->restart();
    EXPECT_FALSE(p->repaint(fixedStep(0))) << "nothing rendered since the restart";
    EXPECT_EQ(p->frame(), 0);
}

TEST_F(PlayerTest, AStructuralReloadCarriesTheBuffersItStillHas) {
    auto p = player();
    ASSERT_TRUE(p);
    for (int i = 0; i < 4; ++i) stepAt(*p);
    writeFile(dir_ / "manifest.json", kTwoBufferManifest);
    auto next = plan();
    ASSERT_TRUE(next.ok()) << next.error().text();
    ReloadReport report = p->reload(std::move(*next));
    EXPECT_TRUE(report.structureChanged);
    EXPECT_TRUE(report.applied);
    EXPECT_TRUE(report.problems.empty());
    EXPECT_EQ(p->manifest().passes.size(), 3u);
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 5.0f) << "Buffer A's content came along";
    std::vector<float> b;
    p->readRgba32f(PassId::BufferB, b);
    EXPECT_EQ(b[0], 5.0f / 16.0f) << "the new Buffer B runs";
}

TEST_F(PlayerTest, AStructuralReloadThatFailsKeepsTheOldShadertoyRunning) {
    auto p = player();
    ASSERT_TRUE(p);
    stepAt(*p);
    writeFile(dir_ / "manifest.json", kTwoBufferManifest);
    writeFile(dir_ / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = nope; }\n");
    auto next = plan();
    ASSERT_TRUE(next.ok());
    ReloadReport report = p->reload(std::move(*next));
    EXPECT_TRUE(report.structureChanged);
    EXPECT_FALSE(report.applied);
    EXPECT_GE(report.problems.size(), 2u) << "Buffer B and Image both fail, both are reported";
    EXPECT_EQ(p->manifest().passes.size(), 2u);
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 2.0f);
}

TEST_F(PlayerTest, ShaderErrorsNameTheUsersFileAndLineEvenAfterAUserLineDirective) {
    writeFile(dir_ / "image.glsl",
              "#line 40\n"
              "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
              "    fragColor = vec4(missing);\n"
              "}\n");
    auto next = plan();
    ASSERT_TRUE(next.ok());
    auto created = Player::create(context_, std::move(*next), PlayerDesc{kW, kH});
    ASSERT_FALSE(created.ok());
    const auto& problems = created.error().diagnostics;
    ASSERT_FALSE(problems.empty());
    EXPECT_EQ(problems[0].file, (dir_ / "image.glsl").string()) << formatDiagnostics(problems);
    EXPECT_EQ(problems[0].pass, "Image");
    EXPECT_EQ(problems[0].line, 41) << "the line the user's #line gives it";
    EXPECT_EQ(formatDiagnostics(problems).find("toyhost header"), std::string::npos) << formatDiagnostics(problems);
}

TEST_F(PlayerTest, ASecondContextComingAndGoingLeavesTheFirstWorking) {
    auto p = player();
    ASSERT_TRUE(p);
    stepAt(*p);
    {
        auto second = createHeadlessContext();
        ASSERT_TRUE(second.ok()) << second.error().text();
        auto other = loadPlayer(*second, dir_, kW, kH);
        ASSERT_TRUE(other);
        stepAt(*other);
        EXPECT_EQ(texel(*other, 0, 0)[0], 1.0f);
    }  // the second player and context are gone; the shared EGL display must not be
    ASSERT_TRUE(context_->makeCurrent().ok());
    stepAt(*p);
    EXPECT_EQ(texel(*p, 0, 0)[0], 2.0f);
}

// Skips only where the device platform is absent (support/EglDevicePlatform.h says exactly when);
// where EGL lists a device, a context that does not start there fails.
TEST_F(PlayerTest, TheEglDevicePlatformRendersTheSame) {
    if (std::optional<std::string> absent = eglDevicePlatformAbsence()) GTEST_SKIP() << *absent;
    auto device = createHeadlessContext(HeadlessOptions{EglPlatform::Device});
    ASSERT_TRUE(device.ok()) << "EGL lists a device, but: " << device.error().text();
    auto other = loadPlayer(*device, dir_, kW, kH);
    ASSERT_TRUE(other);
    for (int i = 0; i < 3; ++i) stepAt(*other);
    EXPECT_EQ(texel(*other, 5, 2), (std::array<float, 4>{3.0f, 2.0f, 5.5f, 2.5f}));
    other.reset();
    ASSERT_TRUE(context_->makeCurrent().ok());
}

}  // namespace
}  // namespace toyhost::testing
