// What a port author reaches for, through the CLI as a user runs it: `toyhost new` starters that
// run at once, `toyhost media`, a manifest's "defaults", near-miss suggestions (a stock media hash
// typo is an error), the unbound-channel warning, NaN/Inf reports (--check-finite), gliding mouse
// moves, `inspect` on a PNG, what --quiet hides and what a run without --out says.
#include "GlTestSupport.h"

#include <cmath>
#include <fstream>

#include "image/ImageFile.h"
#include "manifest/StockMedia.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;


std::string quoted(const fs::path& path) { return "'" + path.string() + "'"; }

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// RGB of pixel (x, y), origin bottom-left like gl_FragCoord.
std::array<int, 3> pixel(const Image8& image, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
}

class PortTools : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = freshOutputDir(std::string("port-tools/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    fs::path dir_;
};

// ---- toyhost new ------------------------------------------------------------------------------

TEST_F(PortTools, NewImageStarterRunsWithTheSiteDefaultCode) {
    auto made = runToyhost("new " + quoted(dir_ / "mine"));
    ASSERT_EQ(made.exitCode, 0) << made.output;
    for (const char* file : {"manifest.json", "image.glsl", "README.md"}) EXPECT_TRUE(fs::exists(dir_ / "mine" / file)) << file;
    auto run = runToyhost("run " + quoted(dir_ / "mine") + " --size 64x36 --frames 1 --quiet --out " + quoted(dir_ / "f.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto image = loadImageFile(dir_ / "f.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    // The site's default: 0.5 + 0.5 cos(iTime + uv.xyx + (0, 2, 4)) at iTime 0.
    const float u = 0.5f / 64.0f, v = 0.5f / 36.0f;
    const std::array<float, 3> expected{0.5f + 0.5f * std::cos(u), 0.5f + 0.5f * std::cos(v + 2.0f),
                                        0.5f + 0.5f * std::cos(u + 4.0f)};
    const auto got = pixel(*image, 0, 0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c] * 255.0f, 1.0f) << "channel " << c;
}

TEST_F(PortTools, NewBufferStarterIsATwoPassFeedbackThatRuns) {
    auto made = runToyhost("new " + quoted(dir_ / "two") + " --passes buffers");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    // Both channels spell out the sampler the loader would give them, for the author to edit.
    std::ifstream manifestFile(dir_ / "two" / "manifest.json");
    const std::string manifest((std::istreambuf_iterator<char>(manifestFile)), std::istreambuf_iterator<char>());
    EXPECT_EQ(count(manifest, "\"filter\": \"linear\""), 2u) << manifest;
    EXPECT_EQ(count(manifest, "\"wrap\": \"clamp\""), 2u) << manifest;
    EXPECT_EQ(count(manifest, "\"vflip\""), 0u) << manifest;  // buffers take none
    auto run = runToyhost("run " + quoted(dir_ / "two") + " --size 96x54 --frames 40 --capture-every 39 --quiet --out " +
                          quoted(dir_ / "f_%02d.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto image = loadImageFile(dir_ / "f_39.png");
    ASSERT_TRUE(image.ok()) << image.error().text();
    // A trail: many lit pixels (the dot alone covers about 11 at this size), fading, on black.
    int lit = 0;
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x) {
            const auto p = pixel(*image, x, y);
            lit += (p[0] + p[1] + p[2]) > 30;
        }
    EXPECT_GT(lit, 45) << "no feedback trail";
    EXPECT_LT(lit, 96 * 54 / 2);
}

TEST_F(PortTools, NewWithPassListAndRefusalToOverwrite) {
    auto made = runToyhost("new " + quoted(dir_ / "toy") + " --passes common,a,b,image");
    ASSERT_EQ(made.exitCode, 0) << made.output;
    for (const char* file : {"common.glsl", "buffer_a.glsl", "buffer_b.glsl", "image.glsl"})
        EXPECT_TRUE(fs::exists(dir_ / "toy" / file)) << file;
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --size 32x18 --frames 2 --quiet");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    auto again = runToyhost("new " + quoted(dir_ / "toy"));
    EXPECT_EQ(again.exitCode, 1) << again.output;
    EXPECT_NE(again.output.find("already exists (use --force to overwrite)"), std::string::npos) << again.output;
    auto bad = runToyhost("new " + quoted(dir_ / "other") + " --passes a,e");
    EXPECT_EQ(bad.exitCode, 2) << bad.output;
    EXPECT_NE(bad.output.find("\"e\" is not a pass"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir_ / "other"));
}

// ---- toyhost media ----------------------------------------------------------------------------

TEST_F(PortTools, MediaListsEveryTableEntryAndWhichFilesAreFound) {
    const StockMediaInfo& lichen = *findStockMedia("Lichen");
    writeFile(dir_ / "media" / "Lichen.jpg", "any bytes: the list does not decode");
    auto list = runToyhost("media --media " + quoted(dir_ / "media"));
    ASSERT_EQ(list.exitCode, 0) << list.output;
    for (const StockMediaInfo& info : stockMediaTable()) {
        const std::string path = stockMediaPath(info);
        const auto at = list.output.find(path);
        ASSERT_NE(at, std::string::npos) << path;
        const std::string line = list.output.substr(list.output.rfind('\n', at) + 1, at - list.output.rfind('\n', at) - 1);
        EXPECT_EQ(line.rfind(std::string(info.name), 0), 0u) << line;
        EXPECT_NE(line.find(std::to_string(info.width) + "x" + std::to_string(info.height)), std::string::npos) << line;
        EXPECT_EQ(line.find("found") != std::string::npos, &info == &lichen) << line;
    }
    // The cubemaps, volumes, videos and music, with their kind.
    for (const StockInputInfo& info : stockInputTable()) {
        const auto at = list.output.find(stockInputPath(info));
        ASSERT_NE(at, std::string::npos) << info.name;
        const std::string line = list.output.substr(list.output.rfind('\n', at) + 1, at - list.output.rfind('\n', at) - 1);
        EXPECT_EQ(line.rfind(std::string(info.name), 0), 0u) << line;
        EXPECT_NE(line.find(stockInputFormName(info.form)), std::string::npos) << line;
    }
}

// ---- manifest defaults ------------------------------------------------------------------------

TEST_F(PortTools, ManifestDefaultsApplyAndTheCommandLineWins) {
    writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(f.x / iResolution.x); }\n");
    writeFile(dir_ / "toy" / "manifest.json",
              R"({"passes": {"Image": {"source": "image.glsl"}}, "defaults": {"size": "40x20", "frames": 3, "fps": 10}})");
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --quiet --out " + quoted(dir_ / "a_%d.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(dir_ / "a_2.png"));
    EXPECT_FALSE(fs::exists(dir_ / "a_3.png"));
    auto image = loadImageFile(dir_ / "a_0.png");
    ASSERT_TRUE(image.ok());
    EXPECT_EQ(image->width, 40);
    EXPECT_EQ(image->height, 20);
    auto overridden = runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8 --frames 1 --quiet --out " + quoted(dir_ / "b_%d.png"));
    ASSERT_EQ(overridden.exitCode, 0) << overridden.output;
    EXPECT_FALSE(fs::exists(dir_ / "b_1.png"));
    image = loadImageFile(dir_ / "b_0.png");
    ASSERT_TRUE(image.ok());
    EXPECT_EQ(image->width, 16);
    EXPECT_NE(overridden.output.find("1 frame at 16x8"), std::string::npos) << overridden.output;
}

// ---- mistakes a port author makes -------------------------------------------------------------

TEST_F(PortTools, StockMediaHashTypoIsAnErrorWithTheRightId) {
    const std::string right = stockMediaPath(*findStockMedia("Gray Noise Medium"));
    std::string typo = right;
    typo[20] = typo[20] == 'a' ? 'b' : 'a';
    writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f); }\n");
    writeFile(dir_ / "toy" / "manifest.json",
              R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"media": ")" + typo + R"("}}}}})");
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8 --out " + quoted(dir_ / "out" / "f.png"));
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("did you mean \"Gray Noise Medium\", " + right + "?"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("passes.\"Image\".channels.iChannel0"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(PortTools, NearMissesInTheManifestSuggestTheRightWord) {
    writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1); }\n");
    writeFile(dir_ / "toy" / "manifest.json", R"({"passes": {"Image ": {"source": "image.glsl"},
        "Buffer A": {"source": "image.glsl", "channels": {"iChanel0": {"buffer": "A"}, "iChannel1": {"bufer": "A"}}}}})");
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8");
    EXPECT_EQ(run.exitCode, 1) << run.output;
    for (const char* hint : {"(did you mean \"Image\"?)", "(did you mean \"iChannel0\"?)", "(did you mean \"buffer\"?)"})
        EXPECT_NE(run.output.find(hint), std::string::npos) << hint << "\n" << run.output;
}

TEST_F(PortTools, UnknownStockIdWarnsThatItsSizeIsAGuess) {
    writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f); }\n");
    writeFile(dir_ / "toy" / "manifest.json",
              R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"media": "/media/a/0123abcd.png"}}}}})");
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8 --quiet");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("warning: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("is a guess"), std::string::npos) << run.output;
}

TEST_F(PortTools, SamplingAnUnboundChannelWarnsOncePerPass) {
    writeFile(dir_ / "toy" / "a.glsl",
              "// iChannel3 in a comment does not count\nvoid mainImage(out vec4 c, in vec2 f) {\n"
              "    c = texture(iChannel1, f) + texture(iChannel2, f) + texture(iChannel1, f.yx);\n}\n");
    writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f / iResolution.xy); }\n");
    writeFile(dir_ / "toy" / "manifest.json", R"({"passes": {"Buffer A": {"source": "a.glsl", "channels": {"iChannel2": {"buffer": "A"}}},
        "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A"}}}}})");
    auto run = runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8 --frames 2");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(count(run.output, "[channel.unbound]"), 1u) << run.output;
    EXPECT_NE(run.output.find((dir_ / "toy" / "a.glsl").string() + ": warning: Buffer A: the code samples iChannel1, which has "
                                                                     "nothing bound"),
              std::string::npos)
        << run.output;
    EXPECT_EQ(run.output.find("iChannel3"), std::string::npos) << run.output;
}

// A Game of Life pasted from the site, whose channel there is nearest: its neighbour reads land on
// texel corners (vec2 of an ivec, no + 0.5), so with the starter's linear every read averages four
// cells and the board dies out. The run says so, naming file, pass, channel, line and the fix; with
// nearest, or with reads at exact centres (where linear and nearest agree), it says nothing.
namespace {
std::string pastedLife(const std::string& coordinate) {
    return "float cell(ivec2 p) { return texture(iChannel0, " + coordinate + ").x; }\n"
           "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
           "    ivec2 p = ivec2(fragCoord);\n"
           "    if (iFrame == 0) { fragColor = vec4(step(0.6, fract(sin(dot(vec2(p), vec2(12.9898, 78.233))) * 43758.5453))); return; }\n"
           "    float n = 0.0;\n"
           "    for (int y = -1; y <= 1; y++) for (int x = -1; x <= 1; x++) if (x != 0 || y != 0) n += cell(p + ivec2(x, y));\n"
           "    float alive = (n == 3.0 || (cell(p) == 1.0 && n == 2.0)) ? 1.0 : 0.0;\n"
           "    fragColor = vec4(alive, alive, alive, 1.0);\n"
           "}\n";
}
}  // namespace

TEST_F(PortTools, ALinearBufferReadOnTexelCornersWarnsAndNearestOrCentresDoNot) {
    auto run = [&](const std::string& name, const std::string& coordinate, const char* filter) {
        writeFile(dir_ / name / "buffer_a.glsl", pastedLife(coordinate));
        writeFile(dir_ / name / "image.glsl",
                  "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n");
        writeFile(dir_ / name / "manifest.json",
                  std::string(R"({"passes": {"Buffer A": {"source": "buffer_a.glsl", "channels": {"iChannel0": {"buffer": "A", "filter": ")") +
                      filter + R"(", "wrap": "clamp"}}}, "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A"}}}}})");
        return runToyhost("run " + quoted(dir_ / name) + " --size 32x24 --frames 12 --capture-every 12 --out " +
                          quoted(dir_ / (name + "_%02d.png")));
    };
    auto lit = [&](const std::string& name) {
        auto image = loadImageFile(dir_ / (name + "_11.png"));
        EXPECT_TRUE(image.ok()) << name;
        int count = 0;
        if (image.ok())
            for (int y = 0; y < image->height; ++y)
                for (int x = 0; x < image->width; ++x) count += pixel(*image, x, y)[0] > 127;
        return count;
    };
    const std::string corners = "vec2(p) / iResolution.xy";
    auto linear = run("corner-linear", corners, "linear");
    ASSERT_EQ(linear.exitCode, 0) << linear.output;
    EXPECT_EQ(count(linear.output, "[channel.filter]"), 1u) << linear.output;
    EXPECT_NE(linear.output.find((dir_ / "corner-linear" / "buffer_a.glsl").string() +
                                 ":1: warning: Buffer A / iChannel0: reads Buffer A with texture() on texel corners"),
              std::string::npos)
        << linear.output;
    EXPECT_NE(linear.output.find("set \"filter\": \"nearest\" in this channel of the manifest"), std::string::npos) << linear.output;
    auto nearest = run("corner-nearest", corners, "nearest");
    ASSERT_EQ(nearest.exitCode, 0) << nearest.output;
    EXPECT_EQ(count(nearest.output, "[channel.filter]"), 0u) << nearest.output;
    // The warning is about a real difference: the automaton lives with nearest and dies with linear.
    EXPECT_GT(lit("corner-nearest"), 20);
    EXPECT_EQ(lit("corner-linear"), 0);

    auto centres = run("centre-linear", "(vec2(p) + 0.5) / iResolution.xy", "linear");
    ASSERT_EQ(centres.exitCode, 0) << centres.output;
    EXPECT_EQ(count(centres.output, "[channel.filter]"), 0u) << centres.output;
    EXPECT_EQ(lit("centre-linear"), lit("corner-nearest"));
    auto a = loadImageFile(dir_ / "centre-linear_11.png");
    auto b = loadImageFile(dir_ / "corner-nearest_11.png");
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->rgba, b->rgba) << "reads at centres: linear gives nearest's picture";
}

// ---- NaN / Inf --------------------------------------------------------------------------------

class NonFinite : public PortTools {
protected:
    void SetUp() override {
        PortTools::SetUp();
        // Buffer A keeps its previous frame and, on frame 5, writes sqrt(-1) at pixel (3, 2) .g.
        writeFile(dir_ / "toy" / "a.glsl",
                  "void mainImage(out vec4 c, in vec2 f) {\n    c = texelFetch(iChannel0, ivec2(f), 0);\n"
                  "    if (iFrame == 5 && ivec2(f) == ivec2(3, 2)) c.g = sqrt(-1.0 - c.r);\n}\n");
        writeFile(dir_ / "toy" / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0); }\n");
        writeFile(dir_ / "toy" / "manifest.json", R"({"passes": {"Buffer A": {"source": "a.glsl", "channels": {"iChannel0": {"buffer": "A"}}},
            "Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "A"}}}}})");
    }
    CommandResult run(const std::string& options) {
        return runToyhost("run " + quoted(dir_ / "toy") + " --size 16x8 --frames 9 --quiet " + options);
    }
};

TEST_F(NonFinite, CheckFiniteNamesThePassAndTheFirstFrame) {
    auto result = run("--check-finite");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(count(result.output, "[buffer.non-finite]"), 1u) << result.output;
    EXPECT_NE(result.output.find("warning: Buffer A: holds non-finite values at iFrame 5 (1 NaN, the first at pixel 3,2 .g); "
                                 "every frame before was finite"),
              std::string::npos)
        << result.output;
}

TEST_F(NonFinite, WithoutTheFlagTheEndOfTheRunIsChecked) {
    auto result = run("");
    EXPECT_NE(result.output.find("Buffer A: holds non-finite values at iFrame 8"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("--check-finite finds the first"), std::string::npos) << result.output;
}

TEST_F(NonFinite, CapturedFloatFramesAreChecked) {
    auto result = run("--capture-pass A --capture-every 3 --out " + quoted(dir_ / "a_%d.exr"));
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(count(result.output, "[buffer.non-finite]"), 1u) << result.output;
    EXPECT_NE(result.output.find("holds non-finite values at iFrame 6"), std::string::npos) << result.output;
}

TEST_F(NonFinite, FiniteBuffersSayNothing) {
    writeFile(dir_ / "toy" / "a.glsl", "void mainImage(out vec4 c, in vec2 f) { c = texelFetch(iChannel0, ivec2(f), 0) + 1.0; }\n");
    auto result = run("--check-finite");
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output.find("non-finite"), std::string::npos) << result.output;
}

// ---- inputs, inspect, quiet, no --out ---------------------------------------------------------

// A glide from (10, 20) on frame 0 to (110, 20) on frame 10, seen through window-probe's column 0
// (iMouse.xy / 255 in R and G).
TEST_F(PortTools, GlidingMouseMovesLinearlyFrameByFrame) {
    writeFile(dir_ / "drag.json", R"([{"frame": 0, "type": "down", "x": 10, "y": 20},
                                      {"frame": 0, "type": "move", "to": {"frame": 10, "x": 110, "y": 20}}])");
    auto run = runToyhost("run " + quoted(sourceDir() / "shadertoys/window-probe") + " --size 160x90 --frames 13 --quiet " +
                          "--mouse-script " + quoted(dir_ / "drag.json") + " --out " + quoted(dir_ / "f_%02d.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int frame = 0; frame <= 12; ++frame) {
        char name[16];
        std::snprintf(name, sizeof name, "f_%02d.png", frame);
        auto image = loadImageFile(dir_ / name);
        ASSERT_TRUE(image.ok()) << image.error().text();
        const auto column0 = pixel(*image, 0, 0);
        EXPECT_EQ(column0[0], 10 + 10 * std::min(frame, 10)) << "iMouse.x on frame " << frame;
        EXPECT_EQ(column0[1], 20) << "iMouse.y on frame " << frame;
    }
}

TEST_F(PortTools, InspectReadsAPngAsLevels) {
    auto run = runToyhost("run " + quoted(sourceDir() / "shadertoys/bench-trivial") + " --size 8x4 --quiet --out " +
                          quoted(dir_ / "f.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    auto inspect = runToyhost("inspect " + quoted(dir_ / "f.png"));
    EXPECT_EQ(inspect.exitCode, 0) << inspect.output;
    EXPECT_NE(inspect.output.find("(8x4, 8-bit levels 0..255)"), std::string::npos) << inspect.output;
    EXPECT_NE(inspect.output.find("A: sum 8160 mean 255 min 255 max 255"), std::string::npos) << inspect.output;
}

TEST_F(PortTools, QuietHidesStandInNoticesAndARunWithoutOutSaysSo) {
    const fs::path toy = sourceDir() / "shadertoys/uniform-probe";  // uses a stock noise stand-in
    auto loud = runToyhost("run " + quoted(toy) + " --size 32x16 --frames 1");
    EXPECT_EQ(loud.exitCode, 0) << loud.output;
    EXPECT_NE(loud.output.find("notice: "), std::string::npos) << loud.output;
    EXPECT_NE(loud.output.find("no files written (no --out"), std::string::npos) << loud.output;
    auto quiet = runToyhost("run " + quoted(toy) + " --size 32x16 --frames 1 --quiet");
    EXPECT_EQ(quiet.exitCode, 0) << quiet.output;
    EXPECT_EQ(quiet.output.find("notice: "), std::string::npos) << quiet.output;
}

}  // namespace
}  // namespace toyhost::testing
