// Broken inputs through the CLI: each gives one clear message naming the file, pass, channel or
// line, a non-zero exit code, and leaves no output files behind.
#include "GlTestSupport.h"

#include <fstream>

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;


bool isEmptyOrAbsent(const fs::path& dir) { return !fs::exists(dir) || fs::is_empty(dir); }

class CliErrors : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = freshOutputDir(std::string("cli-errors/") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        toy_ = dir_ / "toy";
        out_ = dir_ / "out";
        writeFile(toy_ / "image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n");
        writeFile(toy_ / "common.glsl", "float helper() {\n    return 1.0;\n}\n");
    }
    CommandResult run(const std::string& manifest) {
        writeFile(toy_ / "manifest.json", manifest);
        return runToyhost("run '" + toy_.string() + "' --size 32x16 --frames 2 --out '" +
                          (out_ / "f_%02d.png").string() + "' --quiet");
    }
    void expectFailure(const CommandResult& result, std::initializer_list<std::string> mentions) {
        EXPECT_NE(result.exitCode, 0) << result.output;
        for (const std::string& text : mentions)
            EXPECT_NE(result.output.find(text), std::string::npos) << "message lacks \"" << text << "\":\n" << result.output;
        EXPECT_TRUE(isEmptyOrAbsent(out_)) << "output files were left behind";
    }
    fs::path dir_, toy_, out_;
};

TEST_F(CliErrors, BadJsonNamesTheManifestAndLine) {
    auto result = run("{\n  \"passes\": {\n    \"Image\": { \"source\": \"image.glsl\" },\n  }\n}\n");
    expectFailure(result, {(toy_ / "manifest.json").string() + ":4:3: error: invalid JSON"});
}

TEST_F(CliErrors, UnknownBufferNamesPassAndChannel) {
    auto result = run(R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel2": {"buffer": "E"}}}}})");
    expectFailure(result, {"manifest.json", "passes.\"Image\".channels.iChannel2", "buffer \"E\" does not exist"});
}

TEST_F(CliErrors, BufferWithoutPassNamesPassAndChannel) {
    auto result = run(R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"buffer": "B"}}}}})");
    expectFailure(result, {"passes.\"Image\".channels.iChannel0", "reads Buffer B, which this manifest does not define"});
}

TEST_F(CliErrors, MissingSourceFileNamesThePath) {
    auto result = run(R"({"passes": {"Buffer A": {"source": "nope.glsl"}, "Image": {"source": "image.glsl"}}})");
    expectFailure(result, {"passes.\"Buffer A\"", (toy_ / "nope.glsl").string(), "file not found"});
}

TEST_F(CliErrors, MissingTextureFileNamesChannelAndPath) {
    auto result = run(R"({"passes": {"Image": {"source": "image.glsl", "channels": [null, {"texture": "gone.png"}]}}})");
    expectFailure(result, {"channels.iChannel1", (toy_ / "gone.png").string(), "file not found"});
}

TEST_F(CliErrors, CompileErrorNamesPassFileAndLine) {
    writeFile(toy_ / "buffer_a.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    float x = 1.0;\n    c = vec4(y);\n}\n");
    auto result = run(R"({"common": "common.glsl", "passes": {"Buffer A": {"source": "buffer_a.glsl"}, "Image": {"source": "image.glsl"}}})");
    expectFailure(result, {"Buffer A", (toy_ / "buffer_a.glsl").string() + ":3:"});
}

TEST_F(CliErrors, CompileErrorInCommonNamesCommonFileAndLine) {
    writeFile(toy_ / "common.glsl", "float helper() {\n    return undefinedThing;\n}\n");
    auto result = run(R"({"common": "common.glsl", "passes": {"Image": {"source": "image.glsl"}}})");
    expectFailure(result, {"error: Common: ", (toy_ / "common.glsl").string() + ":2:"});
}

TEST_F(CliErrors, MissingMainImageIsReported) {
    writeFile(toy_ / "image.glsl", "void notMain(out vec4 c, in vec2 p) { c = vec4(1.0); }\n");
    auto result = run(R"({"passes": {"Image": {"source": "image.glsl"}}})");
    expectFailure(result, {"Image", "mainImage"});
}

TEST_F(CliErrors, UnwritableOutputLeavesNoPartialFile) {
    writeFile(toy_ / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir_ / "blocker", "a file where a folder should be");
    auto result = runToyhost("run '" + toy_.string() + "' --size 32x16 --frames 1 --out '" +
                             (dir_ / "blocker" / "f.png").string() + "' --quiet");
    EXPECT_NE(result.exitCode, 0);
    EXPECT_NE(result.output.find((dir_ / "blocker").string()), std::string::npos) << result.output;
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
}

TEST_F(CliErrors, BadOptionsAreUsageErrors) {
    writeFile(toy_ / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    const std::string target = "run '" + toy_.string() + "' ";
    EXPECT_EQ(runToyhost(target + "--size 12by4").exitCode, 2);
    EXPECT_EQ(runToyhost(target + "--capture-pass 'Buffer Q'").exitCode, 2);
    EXPECT_EQ(runToyhost(target + "--mouse 3").exitCode, 2);
    auto unnumbered = runToyhost(target + "--frames 3 --out '" + (out_ / "one.png").string() + "'");
    EXPECT_NE(unnumbered.exitCode, 0);
    EXPECT_NE(unnumbered.output.find("%04d"), std::string::npos) << unnumbered.output;
    auto format = runToyhost(target + "--out '" + (out_ / "x.jpg").string() + "'");
    EXPECT_NE(format.exitCode, 0);
    EXPECT_NE(format.output.find(".jpg"), std::string::npos) << format.output;
    auto capture = runToyhost(target + "--capture-pass 'Buffer C' --out '" + (out_ / "x.png").string() + "'");
    EXPECT_NE(capture.exitCode, 0);
    EXPECT_NE(capture.output.find("Buffer C"), std::string::npos) << capture.output;
    EXPECT_TRUE(isEmptyOrAbsent(out_));
}

TEST_F(CliErrors, HelpAndVersionWork) {
    auto help = runToyhost("--help");
    EXPECT_EQ(help.exitCode, 0);
    // Each command on its own line of the Subcommands list, with its description.
    for (const char* line : {"\n  run    ", "\n  import    ", "\n  inspect    "})
        EXPECT_NE(help.output.find(line), std::string::npos) << "no line starting with" << line << "\n" << help.output;
    EXPECT_NE(help.output.find("Usage: toyhost [OPTIONS] SUBCOMMAND"), std::string::npos) << help.output;
    auto runHelp = runToyhost("run --help");
    EXPECT_EQ(runHelp.exitCode, 0);
    for (const char* option : {"--headless", "--size", "--frames", "--fps", "--start-time", "--out", "--capture-every",
                               "--capture-pass", "--mouse", "--mouse-script"})
        EXPECT_NE(runHelp.output.find(option), std::string::npos) << option;
    auto version = runToyhost("--version");
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_NE(version.output.find("toyhost"), std::string::npos);
}

}  // namespace
}  // namespace toyhost::testing
