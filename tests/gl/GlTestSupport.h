// Shared helpers for GL tests: one headless EGL context per test process, a shadertoy loaded
// into a Player (the engine every driver runs), running the CLI, and paths of the repo and
// ../shared.
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

namespace toyhost::testing {

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

// The fixed time step of headless runs: frame n at iTime = n / fps.
inline FrameTime fixedStep(int frame, double fps = 60.0) {
    return FrameTime{frame / fps, 1.0 / fps, fps, glm::vec4(0.0f)};
}

// A shadertoy (folder, manifest or export) in a Player on `context`, with the same loading as
// real runs (images decoded, stand-ins for stock media).
inline std::unique_ptr<Player> loadPlayer(const std::shared_ptr<GlContext>& context, const std::filesystem::path& target,
                                          int width, int height, bool floatImage = false,
                                          TextureAllocator allocate = {}) {
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

// Steps `player` through its next frame at the fixed time step of that frame.
inline void stepAt(Player& player, std::span<const InputEvent> events = {}, bool renderImage = true,
                   double fps = 60.0) {
    player.step(fixedStep(player.frame(), fps), events, renderImage);
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

}  // namespace toyhost::testing
