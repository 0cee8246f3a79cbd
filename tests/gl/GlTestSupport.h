// Shared helpers for GL tests: one EGL surfaceless context per test process, loading a
// shadertoy folder into a Renderer, running the CLI, and paths of the repo and ../shared.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "gl/EglSurfacelessContext.h"
#include "graph/PassGraph.h"
#include "manifest/ManifestLoader.h"
#include "media/MediaResolver.h"
#include "render/Renderer.h"
#include "run/ChannelImages.h"

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
        auto made = createEglSurfacelessContext();
        ASSERT_TRUE(made.ok()) << made.error().message;
        context_ = std::move(*made).release();
    }
    static void TearDownTestSuite() {
        delete context_;
        context_ = nullptr;
    }
    static inline GlContext* context_ = nullptr;
};

// A shadertoy loaded into a renderer, with the same image loading as real runs.
struct LoadedShadertoy {
    ManifestDesc manifest;
    PassGraph graph;
    MediaResolver media;
    std::unique_ptr<ChannelImages> images;
    std::unique_ptr<Renderer> renderer;

    FrameUniforms uniforms(int frame, float fps = 60.0f) const {
        FrameUniforms u;
        u.frame = frame;
        u.time = frame / fps;
        u.timeDelta = 1.0f / fps;
        u.frameRate = fps;
        return u;
    }
};

inline std::unique_ptr<LoadedShadertoy> loadShadertoy(const std::filesystem::path& target, int width,
                                                      int height, bool floatImage = false) {
    auto loaded = std::make_unique<LoadedShadertoy>();
    auto manifest = loadManifest(target);
    EXPECT_TRUE(manifest.ok()) << manifest.error().message;
    if (!manifest.ok()) return nullptr;
    loaded->manifest = std::move(*manifest);
    loaded->graph = buildPassGraph(loaded->manifest);
    for (const auto& [id, file] : loaded->manifest.mediaOverrides) loaded->media.setOverride(id, file);
    loaded->images = std::make_unique<ChannelImages>(loaded->media, nullptr);
    RendererOptions options;
    options.width = width;
    options.height = height;
    options.floatImageTarget = floatImage;
    auto renderer = Renderer::create(loaded->manifest, loaded->graph, options, std::ref(*loaded->images));
    EXPECT_TRUE(renderer.ok()) << renderer.error().message;
    if (!renderer.ok()) return nullptr;
    loaded->renderer = std::move(*renderer);
    return loaded;
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

// Runs the toyhost CLI with `arguments` (already shell-quoted).
inline CommandResult runToyhost(const std::string& arguments) { return runCommand(toyhostBinary(), arguments); }

inline std::filesystem::path freshOutputDir(const std::string& name) {
    std::filesystem::path dir = testOutputDir() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace toyhost::testing
