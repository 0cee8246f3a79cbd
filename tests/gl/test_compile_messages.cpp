// What `toyhost run` prints when a pass does not compile, on the real compiler (Mesa llvmpipe):
// the one-line form "toyhost: FILE:LINE:COL: error: PASS: MESSAGE [CODE]" at the user's true
// position, the user's line with a caret under it, plain words for a missing ';' (on the line it is
// missing from), one line for one typo (no cascade, no list of every overload), the first error
// first, and the same excerpt for Common and for an export's pass. The text rules themselves are
// unit-tested in tests/unit/test_compile_messages.cpp.
#include "GlTestSupport.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

class CompileMessages : public ::testing::Test {
protected:
    void SetUp() override { dir_ = freshOutputDir(std::string("compile-messages/") + ::testing::UnitTest::GetInstance()->current_test_info()->name()); }

    // Runs a folder holding `files` (manifest.json included) and returns its output with the folder
    // written as @D.
    std::string run(const std::vector<std::pair<std::string, std::string>>& files, int expectedExit = 1) {
        for (const auto& [name, text] : files) writeFile(dir_ / name, text);
        const CommandResult result = runToyhost("run '" + dir_.string() + "' --headless --quiet --size 16x8 --frames 1");
        EXPECT_EQ(result.exitCode, expectedExit) << result.output;
        return replaceAll(result.output, dir_.string(), "@D");
    }
    fs::path dir_;
};

const std::string kImageOnly = R"({"passes": {"Image": {"source": "image.glsl"}}})";

// The issue's example: one typo gave 14 lines (12 of them every `mix` overload) and no excerpt.
TEST_F(CompileMessages, OneTypoGivesOneErrorWithTheLineAndTheNameMeant) {
    const std::string output = run({{"manifest.json", kImageOnly},
                                    {"image.glsl", "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                                   "    vec2 uv = fragCoord / iResolution.xy;\n"
                                                   "    vec3 previous = vec3(uv, 0.5);\n"
                                                   "    vec3 col = mix(previus, vec3(1.0), 0.5);\n"
                                                   "    fragColor = vec4(col, 1.0);\n"
                                                   "}\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/image.glsl:4:20: error: Image: `previus' undeclared (did you mean `previous'?) [shader.compile]\n"
              "    4 |     vec3 col = mix(previus, vec3(1.0), 0.5);\n"
              "      |                    ^~~~~~~\n");
}

// The issue's other example: a missing ';' was reported on the next line in parser jargon.
TEST_F(CompileMessages, AMissingSemicolonNamesTheLineItIsMissingFrom) {
    const std::string output = run({{"manifest.json", kImageOnly},
                                    {"image.glsl", "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                                   "    vec2 uv = fragCoord / iResolution.xy\n"
                                                   "\n"
                                                   "    float d = length(uv);\n"
                                                   "    fragColor = vec4(d);\n"
                                                   "}\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/image.glsl:2:41: error: Image: ';' missing at the end of this line (the compiler noticed at "
              "`float' on line 4: syntax error, unexpected BASIC_TYPE_TOK, expecting ',' or ';') [shader.compile]\n"
              "    2 |     vec2 uv = fragCoord / iResolution.xy\n"
              "      |                                         ^\n");
}

// Indentation and comments before the mistake: Mesa counts columns after collapsing them, the
// user reads the file's own columns.
TEST_F(CompileMessages, ColumnsAreTheFilesOwnAfterTabsAndComments) {
    const std::string output = run({{"manifest.json", kImageOnly},
                                    {"image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n"
                                                   "\tfloat  a  =   1.0 /* note */ +  zz;\n"
                                                   "    c = vec4(a);\n"
                                                   "}\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/image.glsl:2:34: error: Image: `zz' undeclared [shader.compile]\n"
              "    2 | \tfloat  a  =   1.0 /* note */ +  zz;\n"
              "      | \t" + std::string(32, ' ') + "^~\n");
}

// A mistake in Common is compiled into every pass: it is reported once, as Common's.
TEST_F(CompileMessages, ACommonErrorComesOnceWithItsExcerpt) {
    const std::string output =
        run({{"manifest.json",
              R"({"common": "common.glsl", "passes": {"Buffer A": {"source": "image.glsl"}, "Image": {"source": "image.glsl"}}})"},
             {"common.glsl", "float helper(float x) {\n    return x * 2.0\n}\n"},
             {"image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(helper(1.0));\n}\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/common.glsl:2:19: error: Common: ';' missing at the end of this line (the compiler noticed at "
              "`}' on line 3: syntax error, unexpected '}', expecting ',' or ';') [shader.compile]\n"
              "    2 |     return x * 2.0\n"
              "      |                   ^\n");
}

// Two passes with errors: in pass order, each error once with its own excerpt, warnings after.
TEST_F(CompileMessages, ErrorsOfSeveralPassesComeInPassOrderEachWithItsExcerpt) {
    const std::string output =
        run({{"manifest.json",
              R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"}, "Image": {"source": "image.glsl"}}})"},
             {"buffer_a.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0) + unknownThing;\n}\n"},
             {"image.glsl", "void mainImage(out vec4 c, in vec2 p) {\n    float a = 1;\n    c = vec4(a);\n}\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/buffer_a.glsl:2:21: error: Buffer A: `unknownThing' undeclared [shader.compile]\n"
              "    2 |     c = vec4(1.0) + unknownThing;\n"
              "      |                     ^~~~~~~~~~~~\n"
              "toyhost: @D/image.glsl:2:5: error: Image: initializer of type int cannot be assigned to variable of type "
              "float (GLSL ES 3.00 never turns an int into a float: write 1.0 rather than 1, or float(n)) [shader.compile]\n"
              "    2 |     float a = 1;\n"
              "      |     ^\n");
}

// An export's passes have no file of their own: the excerpt is the pass's code, its lines counted
// within the pass as the one-line form counts them.
TEST_F(CompileMessages, AnExportsPassGetsItsExcerpt) {
    writeFile(dir_ / "toy.json",
              R"({"Shader": {"info": {"id": "x", "name": "toy"}, "renderpass": [{"inputs": [], "outputs": [{"id": 37, "channel": 0}],)"
              R"( "type": "image", "name": "Image", "code": "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(iGlobalTime);\n}\n"}]}})");
    const CommandResult result = runToyhost("run '" + (dir_ / "toy.json").string() + "' --headless --quiet --size 16x8 --frames 1");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(replaceAll(result.output, dir_.string(), "@D"),
              "toyhost: @D/toy.json [Image]:2:14: error: Image: `iGlobalTime' undeclared (Shadertoy renamed iGlobalTime to "
              "iTime) [shader.compile]\n"
              "    2 |     c = vec4(iGlobalTime);\n"
              "      |              ^~~~~~~~~~~\n");
}

// Issue 27: the linker's "unresolved reference to function `mainImage'" had no line and no hint.
TEST_F(CompileMessages, AMisspeltMainImageNamesThePassTheDeclarationAndTheNearMiss) {
    const std::string output = run({{"manifest.json", R"({"passes": {"Buffer A": {"source": "a.glsl"}, "Image": {"source": "image.glsl", "channels": [{"buffer": "A"}]}}})"},
                                    {"a.glsl", "void mainImg(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n"},
                                    {"image.glsl", "void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = texture(iChannel0, fragCoord); }\n"}});
    EXPECT_EQ(output,
              "toyhost: @D/a.glsl:1:6: error: Buffer A: no `void mainImage(out vec4 fragColor, in vec2 fragCoord)' in "
              "this pass: did you mean this `mainImg'? (names are case-sensitive) (link: unresolved reference to "
              "function `mainImage') [shader.link]\n"
              "    1 | void mainImg(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n"
              "      |      ^~~~~~~\n");
}

}  // namespace
}  // namespace toyhost::testing
