// What a shader person tries first, through the CLI: a lone .glsl file (and `-` on standard input)
// runs as the Image-only shadertoy of a one-pass folder, pixel for pixel; --define switches an
// #ifdef in every pass; a manifest's JSON slip is named by line and column with the line shown.
#include "GlTestSupport.h"
#include "Processes.h"

#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

#include "image/ImageWriters.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

const std::string kImage =
    "void mainImage(out vec4 c, in vec2 f) {\n"
    "    vec2 uv = f / iResolution.xy;\n"
    "    c = vec4(uv, 0.5 + 0.5 * sin(iTime + uv.x * 6.0), 1.0);\n"
    "}\n";

Image8 png(const fs::path& file) {
    Result<Image8> image = readPng(file);
    EXPECT_TRUE(image.ok()) << file << (image.ok() ? "" : ": " + image.error().text());
    return image.ok() ? std::move(*image) : Image8{};
}

std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

const std::string kRun = " --size 48x27 --frames 3 --fps 10 --date 2026-01-01T00:00:00 --quiet";

TEST(ShaderFiles, ALoneGlslFileAndStdinRenderTheOnePassFolder) {
    const fs::path dir = freshOutputDir("shader-files/lone");
    writeFile(dir / "folder/image.glsl", kImage);
    writeFile(dir / "folder/manifest.json", R"({"name": "image", "passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "lone/wave.glsl", kImage);
    CommandResult folder = runToyhost("run " + quoted(dir / "folder") + kRun + " --out " + quoted(dir / "a_%02d.png"));
    ASSERT_EQ(folder.exitCode, 0) << folder.output;
    CommandResult lone = runToyhost("run " + quoted(dir / "lone/wave.glsl") + kRun + " --out " + quoted(dir / "b_%02d.png"));
    ASSERT_EQ(lone.exitCode, 0) << lone.output;
    CommandResult piped = runCommand("/bin/sh", "-c \"cat " + (dir / "lone/wave.glsl").string() + " | DISPLAY= '" +
                                                    toyhostBinary().string() + "' run -" + kRun + " --out " +
                                                    quoted(dir / "c_%02d.png") + "\"");
    ASSERT_EQ(piped.exitCode, 0) << piped.output;
    for (int frame = 0; frame < 3; ++frame) {
        char name[16];
        std::snprintf(name, sizeof name, "_%02d.png", frame);
        const Image8 a = png(dir / ("a" + std::string(name)));
        ASSERT_GT(a.width, 0);
        EXPECT_EQ(png(dir / ("b" + std::string(name))).rgba, a.rgba) << "frame " << frame << " of the lone file";
        EXPECT_EQ(png(dir / ("c" + std::string(name))).rgba, a.rgba) << "frame " << frame << " from stdin";
    }
}

TEST(ShaderFiles, ALoneFileSaysHowItRunsAndTakesTheCommonNextToIt) {
    const fs::path dir = freshOutputDir("shader-files/common");
    writeFile(dir / "toy/image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(level(), 0.0, 0.0, 1.0); }\n");
    writeFile(dir / "toy/common.glsl", "float level() { return 0.25; }\n");
    CommandResult run = runToyhost("run " + quoted(dir / "toy/image.glsl") +
                                   " --size 8x8 --frames 1 --out " + quoted(dir / "f.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("as its Common pass"), std::string::npos) << run.output;
    const Image8 frame = png(dir / "f.png");
    ASSERT_EQ(frame.rgba.size(), 8u * 8u * 4u);
    EXPECT_NEAR(frame.rgba[0], 64, 1);
}

TEST(ShaderFiles, ACompileErrorInALoneFileNamesTheFileAndLine) {
    const fs::path dir = freshOutputDir("shader-files/error");
    writeFile(dir / "bad.glsl", "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(undeclared);\n}\n");
    CommandResult run = runToyhost("run " + quoted(dir / "bad.glsl") + " --size 8x8 --frames 1 --out " + quoted(dir / "f.png"));
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find((dir / "bad.glsl").string() + ":2:"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir / "f.png"));
}

TEST(ShaderFiles, StdinFromATerminalOrNothingIsRefused) {
    CommandResult closed = runCommand("/bin/sh", "-c \"DISPLAY= '" + toyhostBinary().string() +
                                                     "' run - --frames 1 --size 8x8 --out /dev/null <&-\"");
    EXPECT_EQ(closed.exitCode, 2) << closed.output;
    EXPECT_NE(closed.output.find("standard input is closed"), std::string::npos) << closed.output;
}

// Once a defect (issue 46): `run -` reading a pipe whose writer never closes ignored SIGINT and
// SIGTERM until SIGKILL (the stop signals' handler restarts a blocked read), and a Ctrl-C that also
// ended the writer printed the notice, then a compile error for the half-read text. Now the read
// ends at the signal: exit 128 + signal, one message saying so, nothing compiled or written.
TEST(ShaderFiles, ASignalEndsTheReadOfStdin) {
    const fs::path dir = freshOutputDir("shader-files/stdin-signal");
    for (const int signal : {SIGTERM, SIGINT}) {
        for (const bool writerEnds : {false, true}) {
            const std::string what = std::string(strsignal(signal)) + (writerEnds ? ", the writer ending" : "");
            int ends[2];
            ASSERT_EQ(::pipe2(ends, O_CLOEXEC), 0);
            const std::string half = "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(";
            ASSERT_EQ(::write(ends[1], half.data(), half.size()), static_cast<ssize_t>(half.size()));
            BackgroundProcess run(toyhostBinary(),
                                  {"run", "-", "--headless", "--size", "8x8", "--frames", "1", "--out",
                                   (dir / "f.png").string()},
                                  dir / "run.log", {}, ends[0]);
            ::close(ends[0]);
            // Waiting for the text that never ends (the old code: in read(); the new: in poll()).
            EXPECT_TRUE(run.waitUntilBlockedIn({"poll", "pipe_read", "pipe_wait"}, 60)) << what << ": " << run.log();
            run.signal(signal);
            if (writerEnds) ::close(ends[1]);
            EXPECT_EQ(run.wait(60), 128 + signal) << what << ": " << run.log();
            if (!writerEnds) ::close(ends[1]);
            const std::string log = run.log();
            EXPECT_NE(log.find("while the Image code was read from standard input: stopped, nothing was run"),
                      std::string::npos) << what << ": " << log;
            EXPECT_EQ(log.find("stdin:"), std::string::npos) << what << ": no compile error: " << log;
            EXPECT_FALSE(fs::exists(dir / "f.png")) << what;
        }
    }
}

TEST(ShaderFiles, DefineSwitchesAnIfdefInEveryPass) {
    const fs::path dir = freshOutputDir("shader-files/define");
    writeFile(dir / "toy/buffer_a.glsl",
              "void mainImage(out vec4 c, in vec2 f) {\n"
              "#ifdef RED\n    c = vec4(1.0, 0.0, 0.0, 1.0);\n#else\n    c = vec4(0.0, 0.0, 1.0, 1.0);\n#endif\n}\n");
    writeFile(dir / "toy/image.glsl",
              "void mainImage(out vec4 c, in vec2 f) {\n"
              "    c = texelFetch(iChannel0, ivec2(f), 0);\n"
              "#ifdef RED\n    c.g = 1.0;\n#endif\n"
              "#ifdef SHADE\n    c.g = SHADE;\n#endif\n}\n");
    writeFile(dir / "toy/manifest.json",
              R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"}, "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A"}}}}})");
    auto render = [&](const std::string& defines, const std::string& name) {
        CommandResult run = runToyhost("run " + quoted(dir / "toy") + " --size 8x8 --frames 1" + defines + " --out " +
                                       quoted(dir / name) + " --quiet");
        EXPECT_EQ(run.exitCode, 0) << run.output;
        Image8 frame = png(dir / name);
        return frame.rgba.size() >= 4 ? std::vector<int>{frame.rgba[0], frame.rgba[1], frame.rgba[2]} : std::vector<int>{};
    };
    EXPECT_EQ(render("", "none.png"), (std::vector<int>{0, 0, 255}));
    EXPECT_EQ(render(" --define RED", "red.png"), (std::vector<int>{255, 255, 0}));  // both passes switched
    EXPECT_EQ(render(" --define SHADE=0.2 --define SHADE=0.2", "shade.png"), (std::vector<int>{0, 51, 255}));

    CommandResult bad = runToyhost("run " + quoted(dir / "toy") + " --frames 1 --define 2X --out " + quoted(dir / "bad.png"));
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("--define: '2X'"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

TEST(ShaderFiles, AManifestSyntaxErrorShowsTheLineWithACaret) {
    const fs::path dir = freshOutputDir("shader-files/json");
    writeFile(dir / "toy/image.glsl", kImage);
    writeFile(dir / "toy/manifest.json", "{\n  \"passes\": {\n    \"Image\": { \"source\": \"image.glsl\" },\n  }\n}\n");
    CommandResult run = runToyhost("run " + quoted(dir / "toy") + " --frames 1 --out " + quoted(dir / "f.png"));
    EXPECT_EQ(run.exitCode, 1) << run.output;
    const std::string where = (dir / "toy/manifest.json").string() + ":4:3: error: invalid JSON: found '}' after a comma";
    EXPECT_NE(run.output.find(where), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("    4 |   }\n      |   ^\n"), std::string::npos) << run.output;
    EXPECT_EQ(run.output.find("json.exception"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace toyhost::testing
