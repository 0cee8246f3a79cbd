// SourceText: bytes GL must not see in a pass's source are errors with their place; past the cap
// they are counted and said once (a binary file named as a shader has one per byte).
#include <gtest/gtest.h>

#include "core/Defaults.h"
#include "shader/SourceText.h"

using namespace toyhost;

TEST(SourceText, AByteOrderMarkGoesAndCommentsMayHoldAnyText) {
    std::string code = "\xEF\xBB\xBFvoid f() {} // caf\xC3\xA9\n/* \xFF */\n";
    std::vector<Diagnostic> problems;
    checkShaderText(code, "image.glsl", "Image", problems);
    EXPECT_TRUE(problems.empty());
    EXPECT_EQ(code.rfind("void", 0), 0u);
}

TEST(SourceText, EachBadByteIsNamedWithItsPlace) {
    std::string code("float a;\nfloat \xFF b;\nint c\0;\n", 26);
    std::vector<Diagnostic> problems;
    checkShaderText(code, "image.glsl", "Image", problems);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0].line, 2);
    EXPECT_EQ(problems[0].column, 7);
    EXPECT_NE(problems[0].message.find("byte 0xFF"), std::string::npos);
    EXPECT_EQ(problems[1].code, Code::ShaderNul);
    EXPECT_EQ(problems[1].line, 3);
}

TEST(SourceText, PastTheCapTheRestAreCountedAndSaidOnce) {
    std::string code;
    for (int line = 1; line <= 250; ++line) code += "x\xFF;\n";
    std::vector<Diagnostic> problems;
    checkShaderText(code, "image.glsl", "Image", problems);
    ASSERT_EQ(problems.size(), defaults::kMaxShaderTextProblems + 1);
    EXPECT_EQ(problems[defaults::kMaxShaderTextProblems - 1].line, 20);
    const Diagnostic& last = problems.back();
    EXPECT_EQ(last.file, "image.glsl");
    EXPECT_EQ(last.pass, "Image");
    EXPECT_NE(last.message.find("and 230 more"), std::string::npos) << last.message;
    EXPECT_NE(last.message.find("up to line 250"), std::string::npos) << last.message;
}

TEST(SourceText, TheCapCountsThisPassOnlyNotTheProblemsBeforeIt) {
    std::vector<Diagnostic> problems(150);  // another pass's, listed before this one
    std::string code = "x\xFF;\n";
    checkShaderText(code, "buffer_a.glsl", "Buffer A", problems);
    EXPECT_EQ(problems.size(), 151u);
    EXPECT_EQ(problems.back().pass, "Buffer A");
}
