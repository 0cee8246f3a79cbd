// MacroDefines (--define NAME[=VALUE]): what a name may be, one value per name, and where the
// #define lines go in every pass (after the site's header, before Common, the user's line numbers
// unchanged).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shader/MacroDefines.h"
#include "shader/ShaderAssembly.h"

using namespace toyhost;

namespace {

std::string errorOf(std::string_view text) {
    Result<MacroDefine> parsed = parseMacroDefine(text);
    if (parsed.ok()) return "";
    EXPECT_EQ(parsed.error().first().field, "defines");
    EXPECT_EQ(parsed.error().first().code, Code::Usage);
    return parsed.error().first().message;
}

}  // namespace

TEST(MacroDefines, ANameAloneIsOneAndAValueIsKeptAsWritten) {
    EXPECT_EQ(parseMacroDefine("TRUTH").value(), (MacroDefine{"TRUTH", "1"}));
    EXPECT_EQ(parseMacroDefine("STEPS=64").value(), (MacroDefine{"STEPS", "64"}));
    EXPECT_EQ(parseMacroDefine("TINT=vec3(1.0, 0.5, 0.0)").value(), (MacroDefine{"TINT", "vec3(1.0, 0.5, 0.0)"}));
    EXPECT_EQ(parseMacroDefine("EMPTY=").value(), (MacroDefine{"EMPTY", ""}));
    EXPECT_EQ(parseMacroDefine("_x1=a=b").value(), (MacroDefine{"_x1", "a=b"}));
}

TEST(MacroDefines, NamesThatAreNotMacroNamesAreRefusedSayingWhy) {
    EXPECT_NE(errorOf("").find("has no name"), std::string::npos);
    EXPECT_NE(errorOf("=3").find("has no name"), std::string::npos);
    EXPECT_NE(errorOf("1X").find("is not a macro name"), std::string::npos);
    EXPECT_NE(errorOf("A-B=1").find("'A-B' is not a macro name"), std::string::npos);
    EXPECT_NE(errorOf("F(x)=x").find("is not a macro name"), std::string::npos);
    EXPECT_NE(errorOf("GL_FOO").find("reserves"), std::string::npos);
    EXPECT_NE(errorOf("MY__NAME").find("reserves"), std::string::npos);
    EXPECT_NE(errorOf("A=1\n#define B 2").find("one line"), std::string::npos);
}

// Once unclear (issue 46): these reached Mesa's preprocessor, whose errors pointed at
// "<toyhost header>:57:12" without a word of --define, or blamed the user's correct next line.
TEST(MacroDefines, ValuesThatWouldBreakTheLinesAroundThemAreRefusedSayingWhy) {
    EXPECT_EQ(errorOf("A=1\\"), "'A': the value ends with '\\', which would continue the #define onto the line after it");
    EXPECT_EQ(errorOf("A=1 /*"), "'A': the value opens a comment ('/*') that it does not close");
    EXPECT_EQ(errorOf("A=1 /* one */ + 2 /* two"), "'A': the value opens a comment ('/*') that it does not close");
    EXPECT_NE(errorOf("X=#error boom").find("'X': the value holds '#'"), std::string::npos);
    EXPECT_NE(errorOf("X=a ## b").find("the value holds '#'"), std::string::npos);
    EXPECT_EQ(errorOf("defined"), "'defined': 'defined' is the preprocessor's operator and cannot be a macro name");
    EXPECT_NE(errorOf("X=\u00e9").find("'X': the value holds '\u00e9', which is not in GLSL's character set"),
              std::string::npos);
    EXPECT_NE(errorOf("X=\"text\"").find("the value holds '\"'"), std::string::npos);
    EXPECT_NE(errorOf(std::string("X=a\x01")).find("the value holds '\\x01'"), std::string::npos);
    EXPECT_NE(errorOf("X=a\\b").find("only to continue a line"), std::string::npos);
    // What GLSL takes stays taken: comments closed or to the end of the line, every operator.
    EXPECT_EQ(errorOf("A=1 /* one */ + 2"), "");
    EXPECT_EQ(errorOf("A=1 // /* not a comment opened"), "");
    EXPECT_EQ(errorOf("A=(x.y + 1) * 2 - 3 / 4 % 5 < 6 > 7 [8] {9} ^ | & ~ = ! : ; , ?"), "");
    EXPECT_EQ(errorOf("A=\t1"), "");
}

TEST(MacroDefines, ANameTwiceMustKeepItsValue) {
    const std::vector<std::string> same{"A=1", "B", "A=1"};
    EXPECT_EQ(parseMacroDefines(same).value(), (MacroDefines{{"A", "1"}, {"B", "1"}}));
    const std::vector<std::string> differ{"A=1", "A=2"};
    Result<MacroDefines> parsed = parseMacroDefines(differ);
    ASSERT_FALSE(parsed.ok());
    EXPECT_NE(parsed.error().first().message.find("'A' is given twice with different values ('1' and '2')"),
              std::string::npos);
}

TEST(MacroDefines, TheLinesGoAfterTheHeaderBeforeCommonInEveryPass) {
    const MacroDefines defines{{"TRUTH", "1"}, {"STEPS", "64"}};
    EXPECT_EQ(macroDefineLines(defines), "#define TRUTH 1\n#define STEPS 64\n");
    EXPECT_EQ(macroDefineLines({}), "");
    const std::string common = "float helper() { return 1.0; }\n";
    for (PassId pass : {PassId::BufferA, PassId::CubeA, PassId::Image, PassId::Sound}) {
        ShaderInputs in;
        in.pass = pass;
        in.sound = pass == PassId::Sound;
        in.common = &common;
        in.code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(STEPS); }\n";
        in.defines = defines;
        const AssembledShader shader = assembleFragmentShader(in);
        for (const std::string* text : {&shader.text, &shader.plainText}) {
            const std::size_t at = text->find("#define TRUTH 1\n#define STEPS 64\n");
            ASSERT_NE(at, std::string::npos) << passName(pass);
            // After the header's own defines and uniforms, before Common and the pass code.
            EXPECT_LT(text->find("#define HW_PERFORMANCE 1"), at);
            EXPECT_LT(text->find("uniform float     iSampleRate;"), at);
            EXPECT_LT(at, text->find("#line 1000001\n"));
            EXPECT_LT(at, text->find("float helper()"));
            EXPECT_LT(at, text->find("c = vec4(STEPS)"));
        }
        // The user's lines keep their numbers: the pass starts at #line 1 after Common.
        const std::size_t pass1 = shader.text.find("#line 1\n", shader.text.find("float helper()"));
        EXPECT_NE(pass1, std::string::npos);
    }
}

TEST(MacroDefines, WithoutDefinesTheShaderIsUnchanged) {
    ShaderInputs in;
    in.code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
    const AssembledShader plain = assembleFragmentShader(in);
    const MacroDefines none;
    in.defines = none;
    EXPECT_EQ(assembleFragmentShader(in).text, plain.text);
}
