// `toyhost compare A B` through the CLI: exit 0 equal, 1 different, 2 when no answer can be given;
// the table and the JSON say where they first differ; difference images and frames are written
// complete and hold the right pixels (tests/gl/compare/ shadertoys, see test_compare.cpp).
#include "GlTestSupport.h"

#include <nlohmann/json.hpp>
#include <toyhost/Compare.h>

#include "Processes.h"
#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string fixture(const std::string& name) { return "'" + (sourceDir() / "tests/gl/compare" / name).string() + "'"; }

const std::string kSmall = " --size 40x20 --fps 10 --date 2026-01-01T00:00:00";

CommandResult compare(const std::string& a, const std::string& b, const std::string& options) {
    return runToyhost("compare " + fixture(a) + " " + fixture(b) + kSmall + " " + options);
}

// The JSON report on stdout (stderr's lines come before or after it).
nlohmann::json jsonOf(const std::string& output) {
    const std::size_t begin = output.find('{'), end = output.rfind('}');
    EXPECT_NE(begin, std::string::npos) << output;
    if (begin == std::string::npos) return {};
    return nlohmann::json::parse(output.substr(begin, end - begin + 1));
}

TEST(CompareCli, IdenticalShadertoysExitZero) {
    CommandResult r = compare("base", "base", "--frames 4");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("equal: 4 frames of Image at 40x20, identical (PSNR inf)"), std::string::npos) << r.output;
}

TEST(CompareCli, OneConstantChangedDiffersAtFrameZero) {
    CommandResult r = compare("base", "constant", "--frames 3 --json");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    const nlohmann::json report = jsonOf(r.output);
    EXPECT_EQ(report["equal"], false);
    EXPECT_EQ(report["first_differing_frame"], 0);
    EXPECT_EQ(report["fps"], 10.0);
    ASSERT_EQ(report["frames"].size(), 3u);
    EXPECT_EQ(report["frames"][0]["first_differing_pixel"]["x"], 20);
    EXPECT_EQ(report["frames"][0]["first_differing_pixel"]["y"], 0);
    EXPECT_EQ(report["frames"][0]["differing_pixels"], 200);
    EXPECT_EQ(report["frames"][0]["max_diff"], 255);
    EXPECT_NEAR(report["frames"][0]["psnr"].get<double>(), 10.7918, 1e-3);
}

TEST(CompareCli, ATimeDependentDivergenceIsFoundAtItsFrame) {
    CommandResult r = compare("base", "diverge", "--frames 6");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("differ: first at frame 3 (iTime 0.3), pixel (0, 10) from the top left; 3 of 6 frames differ"),
              std::string::npos)
        << r.output;
    CommandResult json = compare("base", "diverge", "--frames 6 --json");
    const nlohmann::json report = jsonOf(json.output);
    EXPECT_EQ(report["first_differing_frame"], 3);
    EXPECT_TRUE(report["frames"][2]["psnr"].is_null()) << "identical frames: PSNR inf is null in JSON";
    EXPECT_EQ(report["min_psnr"].is_number(), true);
}

TEST(CompareCli, ToleranceDecidesTheExitCode) {
    EXPECT_EQ(compare("base", "constant", "--frames 1 --max-diff 255").exitCode, 0);
    EXPECT_EQ(compare("base", "constant", "--frames 1 --max-diff 254").exitCode, 1);
    EXPECT_EQ(compare("base", "constant", "--frames 1 --tolerance-psnr 10").exitCode, 0);  // 10.79 dB
    EXPECT_EQ(compare("base", "constant", "--frames 1 --tolerance-psnr 11").exitCode, 1);
    // The mouse only changes mouse's frames while held: held from frame 0, it differs at once.
    EXPECT_EQ(compare("base", "mouse", "--frames 2").exitCode, 0);
    CommandResult held = compare("base", "mouse", "--frames 2 --mouse 3,4 --json");
    EXPECT_EQ(held.exitCode, 1) << held.output;
    EXPECT_EQ(jsonOf(held.output)["first_differing_frame"], 0);
    CommandResult scripted = compare("base", "mouse", "--frames 4 --json --mouse-script " + fixture("mouse-down.json"));
    EXPECT_EQ(scripted.exitCode, 1) << scripted.output;
    EXPECT_EQ(jsonOf(scripted.output)["first_differing_frame"], 2);
    // A buffer pass, alpha included.
    EXPECT_EQ(compare("buffer", "buffer-alpha", "--frames 1").exitCode, 0);
    EXPECT_EQ(compare("buffer", "buffer-alpha", "--frames 1 --pass A").exitCode, 1);
}

TEST(CompareCli, DifferenceImagesAreWrittenForDifferingFramesAndHoldTheDifference) {
    const fs::path dir = freshOutputDir("compare-cli/diff");
    CommandResult r = compare("base", "diverge", "--frames 5 --diff-out '" + (dir / "diff").string() + "' --frames-out '" +
                                                     (dir / "frames").string() + "'");
    ASSERT_EQ(r.exitCode, 1) << r.output;
    for (int n : {0, 1, 2}) EXPECT_FALSE(fs::exists(dir / "diff" / ("diff_000" + std::to_string(n) + ".png")));
    for (int n : {3, 4}) EXPECT_TRUE(fs::exists(dir / "diff" / ("diff_000" + std::to_string(n) + ".png")));
    std::size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        files += entry.is_regular_file() ? 1 : 0;
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << "a temporary file is left";
    }
    EXPECT_EQ(files, 2u + 2u * 5u) << "2 difference images, A and B for each of 5 frames";
    EXPECT_NE(r.output.find("wrote 2 difference images"), std::string::npos) << r.output;

    // Frame 3's difference image from the frames written, worked out here: |a - b| * 8 per channel.
    Result<Image8> a = loadImageFile(dir / "frames/a_0003.png");
    Result<Image8> b = loadImageFile(dir / "frames/b_0003.png");
    Result<Image8> diff = loadImageFile(dir / "diff/diff_0003.png");
    ASSERT_TRUE(a.ok() && b.ok() && diff.ok());
    ASSERT_EQ(diff->width, 40);
    ASSERT_EQ(diff->height, 20);
    for (std::size_t i = 0; i < diff->rgba.size(); ++i) {
        const int expected = i % 4 == 3 ? 255 : std::min(255, std::abs(int(a->rgba[i]) - int(b->rgba[i])) * 8);
        ASSERT_EQ(int(diff->rgba[i]), expected) << "byte " << i;
    }
    // Rows bottom first (image/Image.h): the bottom half differs in red, the top half not at all.
    EXPECT_GT(diff->rgba[(5 * 40 + 7) * 4 + 0], 0);
    EXPECT_EQ(diff->rgba[(15 * 40 + 7) * 4 + 0], 0);

    // The frames written are the frames `toyhost run` renders.
    const fs::path run = freshOutputDir("compare-cli/run");
    CommandResult ran = runToyhost("run " + fixture("diverge") + kSmall + " --frames 4 --quiet --out '" +
                                   (run / "f_%d.png").string() + "'");
    ASSERT_EQ(ran.exitCode, 0) << ran.output;
    Result<Image8> reference = loadImageFile(run / "f_3.png");
    ASSERT_TRUE(reference.ok());
    EXPECT_EQ(b->rgba, reference->rgba);
}

TEST(CompareCli, ProblemsExitTwo) {
    CommandResult missing = compare("base", "no-such-folder", "--frames 1");
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("no-such-folder"), std::string::npos) << missing.output;
    CommandResult broken = compare("base", "broken", "--frames 1");
    EXPECT_EQ(broken.exitCode, 2) << broken.output;
    EXPECT_NE(broken.output.find("[shader.compile]"), std::string::npos) << broken.output;
    CommandResult noPass = compare("base", "base", "--frames 1 --pass 'Buffer A'");
    EXPECT_EQ(noPass.exitCode, 2) << noPass.output;
    EXPECT_NE(noPass.output.find("no pass Buffer A"), std::string::npos) << noPass.output;
    EXPECT_EQ(compare("base", "base", "--pass 'Cube A'").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--frames 0").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--frames 0x10").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--supersample 0x10").exitCode, 2);
    const std::string both = "compare " + fixture("base") + " " + fixture("diverge");
    CommandResult wrapped = runToyhost(both + " --frames 1 --size 4294967396x20");
    EXPECT_EQ(wrapped.exitCode, 2) << wrapped.output;
    EXPECT_NE(wrapped.output.find("--size 4294967396x20"), std::string::npos) << wrapped.output;
    // Once a defect (issue 46): beyond 16384 a side compare drew and compared one 1024-wide tile
    // and could say "equal"; frames compared in memory are one target, so the size is refused.
    CommandResult wide = runToyhost(both + " --frames 1 --size 20000x20");
    EXPECT_EQ(wide.exitCode, 2) << wide.output;
    EXPECT_NE(wide.output.find("--size: canvas size 20000x20"), std::string::npos) << wide.output;
    EXPECT_NE(wide.output.find("at most 16384x16384"), std::string::npos) << wide.output;
    EXPECT_EQ(compare("base", "base", "--max-diff 256").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--tolerance-psnr nan").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--max-diff 2 --tolerance-psnr 40").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--size 40by20").exitCode, 2);
    EXPECT_EQ(compare("base", "base", "--mouse-script " + fixture("no-such.json")).exitCode, 2);
    EXPECT_EQ(runToyhost("compare " + fixture("base")).exitCode, 2) << "B is required";
    // A --diff-out that cannot be a folder: nothing rendered, nothing written.
    const fs::path dir = freshOutputDir("compare-cli/not-a-folder");
    writeFile(dir / "file", "x");
    CommandResult notFolder = compare("base", "constant", "--frames 1 --diff-out '" + (dir / "file").string() + "'");
    EXPECT_EQ(notFolder.exitCode, 2) << notFolder.output;
}

// SIGINT ends a long comparison after the frame being compared: exit 130, and the files written
// are pairs of complete frames.
TEST(CompareCli, SigintStopsAfterTheFrameWithCompleteFiles) {
    const fs::path dir = freshOutputDir("compare-cli/sigint");
    const std::string base = (sourceDir() / "tests/gl/compare/base").string();
    BackgroundProcess compare(toyhostBinary(),
                              {"compare", base, base, "--size", "40x20", "--frames", "1000000", "--frames-out",
                               (dir / "frames").string()},
                              dir / "compare.log");
    // Waits for the first frame's file (a state, not a time; bounded so that a hang fails).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!fs::exists(dir / "frames/b_0000.png") && compare.running() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(fs::exists(dir / "frames/b_0000.png")) << compare.log();
    compare.signal(SIGINT);
    EXPECT_EQ(compare.wait(60), 130) << compare.log();
    EXPECT_NE(compare.log().find("SIGINT: stopped after"), std::string::npos) << compare.log();
    std::size_t a = 0, b = 0;
    for (const auto& entry : fs::directory_iterator(dir / "frames")) {
        const std::string name = entry.path().filename().string();
        ASSERT_EQ(entry.path().extension(), ".png") << "an unfinished file: " << name;
        (name[0] == 'a' ? a : b) += 1;
        EXPECT_TRUE(loadImageFile(entry.path()).ok()) << name;
    }
    EXPECT_EQ(a, b) << "every compared frame's two files";
    EXPECT_GE(a, 1u);
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// `run` and `compare` share their session flags (tools/toyhost/SessionFlags.h) and the library's
// checks (session/SettingChecks.h): a value one refuses, the other refuses with the same message.
TEST(CompareCli, SessionFlagsAreRefusedWithRunsMessages) {
    const std::string probe = "'" + (sourceDir() / "shadertoys/timeline-probe").string() + "'";
    for (const char* given : {"--size 0x0", "--size -1x10", "--fps 0", "--frames 0", "--start-time 2e9",
                              "--mouse 1e9,3", "--date 2020-13-01"}) {
        const CommandResult run = runToyhost("run " + probe + " --headless " + given);
        const CommandResult compared = runToyhost("compare " + probe + " " + probe + " " + given);
        EXPECT_EQ(run.exitCode, 2) << given << ": " << run.output;
        EXPECT_EQ(compared.exitCode, 2) << given << ": " << compared.output;
        EXPECT_EQ(compared.output, run.output) << given;
        EXPECT_NE(run.output.find("toyhost: error: --"), std::string::npos) << given << ": " << run.output;
    }
}

}  // namespace
}  // namespace toyhost::testing
