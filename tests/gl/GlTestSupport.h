// Shared helpers for GL tests: one headless EGL context per test process, a shadertoy started as a
// SessionCore (what every command runs) and stepped frame by frame, running the CLI, and paths of the
// repo and ../shared. (tests/gl/test_player.cpp tests the Player below the SessionCore directly.)
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "export/LoadShadertoy.h"
#include "gl/HeadlessContext.h"
#include "player/Player.h"
#include "session/SessionCore.h"

#include <toyhost/Session.h>

namespace toyhost {
// The GL tests look at the Player a SessionCore runs; programs use the session's own methods.
struct SessionCoreAccess {
    static Player& player(SessionCore& session) { return *session.player_; }
};
}  // namespace toyhost

namespace toyhost::testing {

inline Player& playerOf(SessionCore& session) { return SessionCoreAccess::player(session); }

inline std::filesystem::path sourceDir() { return TOYHOST_SOURCE_DIR; }
inline std::filesystem::path sharedDir() { return sourceDir() / ".." / "shared"; }
inline std::filesystem::path testOutputDir() { return TOYHOST_TEST_OUTPUT_DIR; }
inline std::filesystem::path toyhostBinary() { return TOYHOST_BIN; }

// Skips the test when the third-party originals are not beside the repository.
#define TOYHOST_REQUIRE_SHARED(relative)                                                   \
    do {                                                                                   \
        if (!std::filesystem::exists(::toyhost::testing::sharedDir() / (relative)))        \
            GTEST_SKIP() << "needs ../shared/" << (relative) << " beside the repository";  \
    } while (0)

class GlTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        auto made = createHeadlessContext();
        ASSERT_TRUE(made.ok()) << made.error().text();
        context_ = std::move(*made);
    }
    static void TearDownTestSuite() { context_.reset(); }
    static inline std::shared_ptr<GlContext> context_;
};

// A watchdog's view of the suite's context for one test: `activity` is attached (what the session
// does with its watchdog) until the end of the scope, also when an assertion ends the test early.
class AttachedActivity {
public:
    AttachedActivity(GlContext& context, RunActivity& activity, bool watchDraws = false) : context_(context) {
        context_.gpuActivity().attach(&activity, watchDraws);
    }
    ~AttachedActivity() { context_.gpuActivity().attach(nullptr, false); }
    AttachedActivity(const AttachedActivity&) = delete;
    AttachedActivity& operator=(const AttachedActivity&) = delete;

private:
    GlContext& context_;
};

// The fixed time step of headless runs: frame n at iTime = n / fps.
inline FrameTime fixedStep(int frame, double fps = 60.0) {
    return FrameTime{frame / fps, 1.0 / fps, fps, glm::vec4(0.0f)};
}

// What sessions started by the tests say: kept, for the tests that look at notices.
struct TestObserver final : SessionObserver {
    std::vector<Diagnostic> notices;
    void notice(const Diagnostic& notice) override { notices.push_back(notice); }
};
inline TestObserver& testObserver() {
    static TestObserver observer;
    return observer;
}

// A shadertoy (folder, manifest or export) started as a SessionCore on `context`, prepared as real runs
// are (images decoded, stand-ins for stock media), without output; `defines` as --define gives them.
inline std::unique_ptr<SessionCore> loadSession(const std::shared_ptr<GlContext>& context, const std::filesystem::path& target,
                                            int width, int height, bool floatImage = false,
                                            std::vector<std::string> defines = {}) {
    SessionOptions options;
    options.target = target;
    options.settings.width = width;
    options.settings.height = height;
    options.settings.floatImage = floatImage;
    options.settings.defines = std::move(defines);
    auto plan = prepareSession(options);
    EXPECT_TRUE(plan.ok()) << plan.error().text();
    if (!plan.ok()) return nullptr;
    auto session = SessionCore::start(std::move(*plan), context, testObserver());
    EXPECT_TRUE(session.ok()) << session.error().text();
    if (!session.ok()) return nullptr;
    return std::move(*session);
}

// Renders the session's next frame at the fixed time step of that frame.
inline void stepAt(SessionCore& session, std::span<const InputEvent> events = {}, double fps = 60.0) {
    const Status rendered = session.renderFrame(fixedStep(playerOf(session).frame(), fps), events);
    EXPECT_TRUE(rendered.ok()) << rendered.error().text();
}

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs `binary` with `arguments` (already shell-quoted) and captures its output.
inline CommandResult runCommand(const std::filesystem::path& binary, const std::string& arguments) {
    CommandResult result;
    const std::string command = "'" + binary.string() + "' " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    char chunk[4096];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, pipe)) > 0) result.output.append(chunk, n);
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

// Runs the toyhost CLI with `arguments` (already shell-quoted), without a display, so that runs
// are headless by default as on CI (window mode has its own tests, tests/window).
inline CommandResult runToyhost(const std::string& arguments) {
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    return runCommand(toyhostBinary(), arguments);
}

// Writes `text` to `path`, creating its folders.
inline void writeFile(const std::filesystem::path& path, const std::string& text) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
}

inline std::filesystem::path freshOutputDir(const std::string& name) {
    std::filesystem::path dir = testOutputDir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// An Image-only shadertoy of `imageCode` written to `dir`, rendered for one frame at width x height
// through the public Session on toyhost's GL thread: its RGBA8 pixels, top row first (empty, with
// the test failed, when it does not load, start or render).
inline std::vector<std::uint8_t> renderImageOnce(const std::filesystem::path& dir, const std::string& imageCode,
                                                 int width = 4, int height = 4) {
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", imageCode);
    Result<Shadertoy> toy = Shadertoy::load(dir);
    if (!toy.ok()) {
        ADD_FAILURE() << toy.error().text();
        return {};
    }
    std::vector<std::uint8_t> pixels;
    runOnGlThread([&] {
        SessionSettings settings;
        settings.width = width;
        settings.height = height;
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*toy, settings);
        if (!made.ok()) {
            ADD_FAILURE() << made.error().text();
            return;
        }
        if (Status stepped = (*made)->step(); !stepped.ok()) {
            ADD_FAILURE() << stepped.error().text();
            return;
        }
        pixels.resize(static_cast<std::size_t>(width) * height * 4);
        if (Status read = (*made)->read("Image", pixels); !read.ok()) {
            ADD_FAILURE() << read.error().text();
            pixels.clear();
        }
    });
    return pixels;
}

}  // namespace toyhost::testing
