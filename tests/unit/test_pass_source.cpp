// PassSource: which passes get the browser-style expansion prepared (a cpp child, run while
// planning, off the GL thread), and what it holds.
#include <gtest/gtest.h>

#include <string>

#include "shader/PassSource.h"

using namespace toyhost;

namespace {

TEST(PassSource, FunctionLikeMacrosAreFound) {
    EXPECT_TRUE(definesFunctionMacro("#define NEG(x) -x\n"));
    EXPECT_TRUE(definesFunctionMacro("float a;\n  #  define\tR(a) mat2(cos(a))\n"));
    EXPECT_FALSE(definesFunctionMacro("#define PI 3.14159\n"));
    EXPECT_FALSE(definesFunctionMacro("#define PI (3.14159)\n")) << "object-like: a space before the parenthesis";
    EXPECT_FALSE(definesFunctionMacro("// #define in a comment's middle is not at a line's start\nfloat x;"));
    EXPECT_FALSE(definesFunctionMacro("#defined(x)\n"));
    EXPECT_FALSE(definesFunctionMacro(""));
}

PassDesc imagePass(std::string code) {
    PassDesc pass;
    pass.id = PassId::Image;
    pass.code = std::move(code);
    pass.sourceName = "image.glsl";
    return pass;
}

TEST(PassSource, APassWithAFunctionLikeMacroGetsItsExpansionPrepared) {
    ManifestDesc manifest;
    const PassDesc pass = imagePass("#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(NEG(-.5)); }\n");
    const PassSource source = preparePassSource(manifest, pass);
    ASSERT_TRUE(source.browserText) << "cpp must be installed (Debian's cpp)";
    ASSERT_TRUE(source.browserPlainText);
    EXPECT_EQ(source.browserText->find("NEG"), std::string::npos) << *source.browserText;
    EXPECT_NE(source.browserText->find("- -.5"), std::string::npos) << "tokens kept apart, as browsers do";
    EXPECT_EQ(source.browserText->rfind("#version", 0), 0u) << "#version stays the first line";
}

TEST(PassSource, APassWithoutOneRunsNoPreprocessor) {
    ManifestDesc manifest;
    const PassSource source =
        preparePassSource(manifest, imagePass("#define K 0.5\nvoid mainImage(out vec4 c, in vec2 f) { c = vec4(K); }\n"));
    EXPECT_FALSE(source.browserText);
    EXPECT_FALSE(source.browserPlainText);
    EXPECT_NE(source.text.find("void mainImage"), std::string::npos);
}

TEST(PassSource, CommonsMacrosCount) {
    ManifestDesc manifest;
    manifest.commonSource = "common.glsl";
    manifest.commonName = "common.glsl";
    manifest.commonCode = "#define TWICE(x) (2.0 * (x))\n";
    const PassSource source =
        preparePassSource(manifest, imagePass("void mainImage(out vec4 c, in vec2 f) { c = vec4(TWICE(0.25)); }\n"));
    EXPECT_TRUE(source.browserText);
}

}  // namespace
