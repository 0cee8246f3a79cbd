// What a user reads when a pass does not compile (shader/CompileMessages, shader/SourceExcerpt):
// Mesa's real messages for real mistakes (captured from llvmpipe, Mesa 22.3: the logs below are
// its exact text) turned into the user's position, an excerpt with a caret, plain words for the
// parser's jargon, the first error first and no cascades of follow-on errors. The CLI's output of
// the same mistakes is tested in tests/gl/test_compile_messages.cpp.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "shader/CompileMessages.h"
#include "shader/CompilerLog.h"
#include "shader/SourceExcerpt.h"

using namespace toyhost;

namespace {

const std::string kFile = "/toy/image.glsl";
const std::string kCommonFile = "/toy/common.glsl";

// Mesa's log for `code` (as toyhost numbers the pass: line 1 is the pass's first line) made readable.
std::vector<Diagnostic> explain(const std::string& log, const std::string& code, const std::string& common = "") {
    std::vector<CompileSource> sources{{kFile, code}};
    if (!common.empty()) sources.push_back({kCommonFile, common});
    return explainCompileProblems(parseCompilerLog(log, {"Image", kFile, kCommonFile}), sources);
}

std::string text(const std::vector<Diagnostic>& problems) { return formatDiagnostics(problems, "toyhost: "); }

}  // namespace

// ---- the two examples ------------------------------------------------------------------

const std::string kTypo = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                          "    vec2 uv = fragCoord / iResolution.xy;\n"
                          "    vec3 previous = vec3(uv, 0.5);\n"
                          "    vec3 col = mix(previus, vec3(1.0), 0.5);\n"
                          "    fragColor = vec4(col, 1.0);\n"
                          "}\n";
// 14 lines from one typo: the undeclared name, a failed overload with its 11 candidates, and a
// warning that follows from the failed initialiser.
const std::string kTypoLog = "0:4(17): error: `previus' undeclared\n"
                             "0:4(13): error: no matching function for call to `mix(error, vec3, float)'; candidates are:\n"
                             "0:4(13): error:    float mix(float, float, float)\n"
                             "0:4(13): error:    vec2 mix(vec2, vec2, float)\n"
                             "0:4(13): error:    vec3 mix(vec3, vec3, float)\n"
                             "0:4(13): error:    vec4 mix(vec4, vec4, float)\n"
                             "0:4(13): error:    vec2 mix(vec2, vec2, vec2)\n"
                             "0:4(13): error:    vec3 mix(vec3, vec3, vec3)\n"
                             "0:4(13): error:    vec4 mix(vec4, vec4, vec4)\n"
                             "0:4(13): error:    float mix(float, float, bool)\n"
                             "0:4(13): error:    vec2 mix(vec2, vec2, bvec2)\n"
                             "0:4(13): error:    vec3 mix(vec3, vec3, bvec3)\n"
                             "0:4(13): error:    vec4 mix(vec4, vec4, bvec4)\n"
                             "0:5(19): warning: `col' used uninitialized\n";

TEST(CompileMessages, OneTypoIsOneErrorWithTheLineACaretAndTheNameMeant) {
    EXPECT_EQ(text(explain(kTypoLog, kTypo)),
              "toyhost: /toy/image.glsl:4:20: error: Image: `previus' undeclared (did you mean `previous'?) [shader.compile]\n"
              "    4 |     vec3 col = mix(previus, vec3(1.0), 0.5);\n"
              "      |                    ^~~~~~~");
}

TEST(CompileMessages, AMissingSemicolonIsNamedOnTheLineItIsMissingFrom) {
    const std::string code = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                             "    vec2 uv = fragCoord / iResolution.xy\n"
                             "\n"
                             "    float d = length(uv);\n"
                             "    fragColor = vec4(d);\n"
                             "}\n";
    EXPECT_EQ(text(explain("0:4(2): error: syntax error, unexpected BASIC_TYPE_TOK, expecting ',' or ';'\n", code)),
              "toyhost: /toy/image.glsl:2:41: error: Image: ';' missing at the end of this line (the compiler noticed "
              "at `float' on line 4: syntax error, unexpected BASIC_TYPE_TOK, expecting ',' or ';') [shader.compile]\n"
              "    2 |     vec2 uv = fragCoord / iResolution.xy\n"
              "      |                                         ^");
}

// ---- missing ';' in its other shapes --------------------------------------------------------------

TEST(CompileMessages, MissingSemicolonBeforeACommentOrABraceOrAKeyword) {
    // Before '}' (a function's last statement), with a comment and blank lines in between.
    std::vector<Diagnostic> d = explain("0:5(1): error: syntax error, unexpected '}', expecting ',' or ';'\n",
                                        "float f(float x) {\n    return x * 2.0   // doubled\n\n    // done\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].column, 19);
    EXPECT_EQ(d[0].message.rfind("';' missing at the end of this line (the compiler noticed at `}' on line 5", 0), 0u)
        << d[0].message;
    // Before `if` (Mesa's IF), at file scope before `void` (VOID_TOK).
    d = explain("0:4(2): error: syntax error, unexpected IF, expecting ',' or ';'\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    float a = 1.0;\n    a += 2.0\n    if (a > 1.0) a = 0.0;\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 3);
    EXPECT_EQ(d[0].column, 13);
    d = explain("0:2(1): error: syntax error, unexpected VOID_TOK, expecting ',' or ';'\n",
                "const float PI = 3.14159\nvoid mainImage(out vec4 c, in vec2 p) { c = vec4(PI); }\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 1);
    EXPECT_EQ(d[0].column, 25);
}

// The line before, as the compiler saw it: directives are not code, and the branch above an #else
// was not compiled with the one below it (Mesa reports the `const' of line 7 at 7(2)).
TEST(CompileMessages, MissingSemicolonBeforeAnElseBranchIsFoundAboveTheIf) {
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    float depth = max(p.y, 0.0)    // no ';'\n"
                             "    // water\n"
                             "#ifdef LAKE\n"
                             "    const vec3 K = vec3(0.5);\n"
                             "#else\n"
                             "    const vec3 K = vec3(0.4);\n"
                             "#endif\n"
                             "    c = vec4(K * depth, 1.0);\n"
                             "}\n";
    const std::vector<Diagnostic> d =
        explain("0:7(2): error: syntax error, unexpected CONST_TOK, expecting ',' or ';'\n", code);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].column, 32);
    EXPECT_EQ(d[0].message.rfind("';' missing at the end of this line (the compiler noticed at `const' on line 7", 0), 0u)
        << d[0].message;
}

// A token in the middle of a line is not a missing ';' at the end of the one before: the token is
// named instead of Mesa's class for it.
TEST(CompileMessages, AnUnexpectedTokenInsideALineIsNamed) {
    const std::vector<Diagnostic> d =
        explain("0:2(16): error: syntax error, unexpected FLOATCONSTANT, expecting ',' or ';'\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    float a = 1.0 2.0;\n    c = vec4(a);\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].column, 19);
    EXPECT_EQ(d[0].message, "syntax error, unexpected `2.0' (FLOATCONSTANT), expecting ',' or ';'");
    EXPECT_EQ(d[0].excerpt, "    2 |     float a = 1.0 2.0;\n      |                   ^~~\n");
}

// ---- brackets -------------------------------------------------------------------------------------

TEST(CompileMessages, ParenthesesAndBraces) {
    std::vector<Diagnostic> d = explain("0:3(31): error: syntax error, unexpected ';', expecting ')' or ','\n",
                                        "void mainImage(out vec4 c, in vec2 p) {\n    vec2 uv = p;\n"
                                        "    fragColor = vec4(uv, 0.0, 1.0;\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].column, 34);
    EXPECT_EQ(d[0].message.rfind("a ')' is missing before this ';' (syntax error", 0), 0u) << d[0].message;

    d = explain("0:2(16): error: syntax error, unexpected '{', expecting ')'\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    if (p.x > 0.5 {\n        c = vec4(1.0);\n    }\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].column, 19);
    EXPECT_EQ(d[0].message.rfind("a ')' is missing before this '{' (syntax error", 0), 0u) << d[0].message;

    // A function's '}' forgotten: the next function's '{' is where the parser stops.
    d = explain("0:4(18): error: syntax error, unexpected '{', expecting ';'\n",
                "float f(float x) {\n    return x;\n\n"
                "float g(float x) {\n    return x;\n}\n");
    ASSERT_EQ(d.size(), 1u) << text(d);
    EXPECT_EQ(d[0].line, 4);
    EXPECT_EQ(d[0].column, 18);
    EXPECT_EQ(d[0].message.rfind("a '}' is missing above: the block opened on line 1 is never closed, so this '{' is "
                                 "read inside it (syntax error",
                                 0),
              0u)
        << d[0].message;

    d = explain("0:2(40): error: syntax error, unexpected ')', expecting ',' or ';'\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    vec2 uv = (fragCoord / iResolution.xy));\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].column, 43);
    EXPECT_EQ(d[0].message.rfind("one ')' too many here", 0), 0u) << d[0].message;

    // The file ends inside a block: the block whose '}' is missing is found by indentation (the
    // last '}' is indented like the function, so it closes the function, not the if).
    d = explain("0:6(2): error: syntax error, unexpected end of file\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    vec2 uv = p;\n    if (uv.x > 0.5) {\n        uv.x = 1.0;\n"
                "    c = vec4(uv, 0.0, 1.0);\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 3);
    EXPECT_EQ(d[0].column, 21);
    EXPECT_EQ(d[0].message, "the code ends inside a block: a '}' is missing (the block opened on line 3 is never "
                            "closed) (syntax error, unexpected end of file)");

    d = explain("0:4(1): error: syntax error, unexpected '}', expecting end of file\n",
                "void mainImage(out vec4 c, in vec2 p) {\n    c = vec4(1.0);\n}\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].message.rfind("one '}' too many", 0), 0u) << d[0].message;
    EXPECT_EQ(d[0].excerpt, "    4 | }\n      | ^\n");
}

// ---- names ---------------------------------------------------------------------------------------

TEST(CompileMessages, HintsForNamesAndTypes) {
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n"
                             "    float t = iGlobalTime;\n"
                             "    gl_FragColor = vec4(helper(t));\n"
                             "    float a = 1;\n"
                             "    float b = a * 2;\n"
                             "    float input = 1.0;\n"
                             "    c = texture2D(iChannel0, p);\n"
                             "    c.x = lenght(p);\n"
                             "}\n"
                             "float helper(float x) { return x; }\n";
    const std::vector<Diagnostic> d = explain("0:2(12): error: `iGlobalTime' undeclared\n"
                                              "0:3(2): error: `gl_FragColor' undeclared\n"
                                              "0:3(22): error: no function with name 'helper'\n"
                                              "0:4(2): error: initializer of type int cannot be assigned to variable of type float\n"
                                              "0:5(12): error: could not implicitly convert operands to arithmetic operator\n"
                                              "0:6(8): error: illegal use of reserved word `input'\n"
                                              "0:6(8): error: syntax error, unexpected ERROR_TOK, expecting ',' or ';'\n"
                                              "0:7(7): error: no function with name 'texture2D'\n"
                                              "0:8(8): error: no function with name 'lenght'\n",
                                              code);
    std::vector<std::string> messages;
    for (const Diagnostic& problem : d) messages.push_back(problem.message);
    EXPECT_EQ(messages,
              (std::vector<std::string>{
                  "`iGlobalTime' undeclared (Shadertoy renamed iGlobalTime to iTime)",
                  "`gl_FragColor' undeclared (a Shadertoy pass writes its colour to mainImage's first parameter, out vec4 fragColor)",
                  "no function with name 'helper' (helper is defined on line 10, below this call: GLSL needs a function "
                  "defined or declared above its first use)",
                  "initializer of type int cannot be assigned to variable of type float (GLSL ES 3.00 never turns an int "
                  "into a float: write 1.0 rather than 1, or float(n))",
                  "could not implicitly convert operands to arithmetic operator (int and float do not mix in GLSL ES "
                  "3.00: write 2.0 rather than 2, or convert with float(n))",
                  "illegal use of reserved word `input' (`input' is reserved in GLSL ES 3.00: give it another name)",
                  "no function with name 'texture2D' (GLSL ES 3.00, which Shadertoy uses, calls it texture)",
                  "no function with name 'lenght' (did you mean `length'?)"}));
    // The caret goes under the name each message is about.
    EXPECT_EQ(d[2].column, 25);
    EXPECT_EQ(d[2].excerpt, "    3 |     gl_FragColor = vec4(helper(t));\n      |                         ^~~~~~\n");
}

// ---- order, follow-ons, candidates ---------------------------------------------------------------

TEST(CompileMessages, ErrorsComeBeforeWarningsAndFollowOnErrorsGo) {
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n    int unused;\n    float a = 1.0 + zz;\n"
                             "    c = vec4(a);\n}\n";
    const std::vector<Diagnostic> d = explain("0:2(6): warning: unused variable `unused'\n"
                                              "0:3(18): error: `zz' undeclared\n"
                                              "0:3(12): error: operands to arithmetic operators must be numeric\n"
                                              "0:2(12): error: RHS of `||' must be scalar boolean\n",
                                              code);
    ASSERT_EQ(d.size(), 2u) << text(d);
    EXPECT_EQ(d[0].message, "`zz' undeclared");
    EXPECT_EQ(d[0].column, 21);
    EXPECT_EQ(d[1].severity, Severity::Warning);
}

// A real overload mismatch keeps its closest candidate, and says how many more there are.
TEST(CompileMessages, CandidateListsAreFoldedToTheClosestCandidate) {
    const std::string code = "void mainImage(out vec4 c, in vec2 p) {\n    vec3 a = mix(vec3(0.0), 1.0, true);\n}\n";
    const std::vector<Diagnostic> d = explain(
        "0:2(11): error: no matching function for call to `mix(vec3, float, bool)'; candidates are:\n"
        "0:2(11): error:    float mix(float, float, float)\n0:2(11): error:    vec3 mix(vec3, vec3, float)\n"
        "0:2(11): error:    float mix(float, float, bool)\n0:2(11): error:    vec3 mix(vec3, vec3, bvec3)\n",
        code);
    ASSERT_EQ(d.size(), 1u) << text(d);
    EXPECT_EQ(d[0].message, "no matching function for call to `mix(vec3, float, bool)'; candidates are: "
                            "float mix(float, float, bool) ... 3 more candidates");
}

// ---- where the user's own numbering rules ---------------------------------------------------------

TEST(CompileMessages, AUsersLineDirectiveKeepsTheCompilersPositionsAndGivesNoExcerpt) {
    const std::string code = "#line 100\nvoid mainImage(out vec4 c, in vec2 p) {\n    c = vec4(zz);\n}\n";
    const std::vector<Diagnostic> d = explain("0:101(11): error: `zz' undeclared\n", code);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 101);
    EXPECT_EQ(d[0].column, 11);
    EXPECT_EQ(d[0].excerpt, "");
}

TEST(CompileMessages, ProblemsInCommonGetCommonsExcerpt) {
    const std::vector<Diagnostic> d =
        explain("0:1000003(1): error: syntax error, unexpected '}', expecting ',' or ';'\n",
                "void mainImage(out vec4 c, in vec2 p) { c = vec4(1.0); }\n", "float helper() {\n    return 1.0\n}\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].file, kCommonFile);
    EXPECT_EQ(d[0].line, 2);
    EXPECT_EQ(d[0].column, 15);
    EXPECT_EQ(d[0].excerpt, "    2 |     return 1.0\n      |               ^\n");
}

// ---- SourceView ----------------------------------------------------------------------------------

// Mesa's column counts the line after its preprocessor made every run of whitespace and comments
// one space (each column below was reported by Mesa for the token named).
TEST(SourceView, CompilerColumnsCountCollapsedWhitespaceAndComments) {
    const SourceView view("void f() {\n"
                          "\tfloat  a  =   1.0  +  zz;\n"                                    // zz: Mesa 2(18)
                          "    /* c */ float b = 1.0 /* long comment here */ + yy;\n"       // yy: Mesa 3(18)
                          "    float b = /* multi\n"                                          // rr: Mesa 4(18)
                          "    line */ 1.0 + rr;\n"
                          "}\n");
    EXPECT_EQ(view.fromCompilerPosition(2, 18).column, 24);
    EXPECT_EQ(view.fromCompilerPosition(2, 18).line, 2);
    EXPECT_EQ(view.fromCompilerPosition(3, 18).column, 53);
    // A block comment across lines joins them: the token after it is on the next line.
    EXPECT_EQ(view.fromCompilerPosition(4, 18).line, 5);
    EXPECT_EQ(view.fromCompilerPosition(4, 18).column, 19);
    // Past the end of the line: just after its last character.
    EXPECT_EQ(view.fromCompilerPosition(6, 2).column, 2);
    EXPECT_EQ(view.tokenAt(2, 13), "");
    EXPECT_EQ(view.tokenAt(2, 16), "1.0");
    EXPECT_EQ(view.tokenAt(2, 21), "+");
    EXPECT_EQ(view.tokenAt(2, 24), "zz");
    EXPECT_EQ(view.lastCodeColumn(3), 55);
    EXPECT_TRUE(view.inComment(3, 5));
}

TEST(SourceView, ExcerptsKeepTabsAndCutLongLines) {
    EXPECT_EQ(formatExcerpt("\tfloat a = zz;", 12, 12, 2), "   12 | \tfloat a = zz;\n      | \t          ^~\n");
    // UTF-8 in a comment before the column takes one place per character.
    EXPECT_EQ(formatExcerpt("/* \xc3\xa9 */ x;", 1, 10), "    1 | /* \xc3\xa9 */ x;\n      | " + std::string(8, ' ') + "^\n");
    const std::string longLine = std::string(300, 'a') + " zz " + std::string(300, 'b');
    const std::string excerpt = formatExcerpt(longLine, 7, 302, 2);
    EXPECT_LT(excerpt.size(), 300u);
    const std::size_t caret = excerpt.find('^') - excerpt.rfind('\n', excerpt.find('^'));
    const std::size_t zz = excerpt.find("zz") + 1;
    EXPECT_EQ(caret, zz) << excerpt;
}

// ---- issue 27: entry points, a ';' before '}', macros that refer to themselves ----------------

// Mesa's linker names the missing function with no position; the pass's near miss is the place.
TEST(CompileMessages, AMisspeltMainImageIsNamedWithTheDeclarationExpected) {
    const std::string code = "void mainimage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n";
    EXPECT_EQ(text(explain("error: unresolved reference to function `mainImage'\n", code)),
              "toyhost: /toy/image.glsl:1:6: error: Image: no `void mainImage(out vec4 fragColor, in vec2 fragCoord)' "
              "in this pass: did you mean this `mainimage'? (names are case-sensitive) (link: unresolved reference to "
              "function `mainImage') [shader.compile]\n"
              "    1 | void mainimage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n"
              "      |      ^~~~~~~~~");
    const std::string shortened = "void mainImg(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0); }\n";
    EXPECT_NE(text(explain("error: unresolved reference to function `mainImage'\n", shortened)).find("did you mean this `mainImg'"),
              std::string::npos);
}

TEST(CompileMessages, AMainImageWithOtherParametersIsPointedAt) {
    const std::string code = "void mainImage(out vec4 fragColor) { fragColor = vec4(1.0); }\n";
    const std::vector<Diagnostic> problems = explain("error: unresolved reference to function `mainImage'\n", code);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].line, 1);
    EXPECT_EQ(problems[0].column, 6);
    EXPECT_EQ(problems[0].message,
              "no `void mainImage(out vec4 fragColor, in vec2 fragCoord)' in this pass: the `mainImage' defined here "
              "has other parameters (link: unresolved reference to function `mainImage')");
}

TEST(CompileMessages, NoNearMissStillSaysWhatThePassLacks) {
    const std::vector<Diagnostic> problems =
        explain("error: unresolved reference to function `mainImage'\n", "float helper(float x) { return x; }\n");
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].line, 0);
    EXPECT_EQ(problems[0].message, "no `void mainImage(out vec4 fragColor, in vec2 fragCoord)' in this pass (link: "
                                   "unresolved reference to function `mainImage')");
}

TEST(CompileMessages, AGlslSandboxMainSaysWhatToWriteInstead) {
    const std::string code = "#ifdef GL_ES\nprecision mediump float;\n#endif\nuniform float time;\n"
                             "uniform vec2 resolution;\nvoid main(void) {\n"
                             "    vec2 p = gl_FragCoord.xy / resolution;\n"
                             "    gl_FragColor = vec4(p, sin(time), 1.0);\n}\n";
    const std::vector<Diagnostic> problems = explain("0:6(6): error: function `main' redefined\n"
                                                     "0:8(2): error: `gl_FragColor' undeclared\n"
                                                     "0:8(2): error: value of type vec4 cannot be assigned to variable of type error\n",
                                                     code);
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0].line, 6);
    EXPECT_EQ(problems[0].message.rfind("a Shadertoy pass defines mainImage, not main: ", 0), 0u) << problems[0].message;
    EXPECT_NE(problems[0].message.find("write `void mainImage(out vec4 fragColor, in vec2 fragCoord)' instead of `void main()'"),
              std::string::npos);
    EXPECT_NE(problems[0].message.find("(function `main' redefined)"), std::string::npos);
    EXPECT_EQ(problems[1].line, 8);
}

TEST(CompileMessages, ASemicolonMissingBeforeABraceOnTheSameLine) {
    const std::string code = "void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0) }\n";
    EXPECT_EQ(text(explain("0:1(79): error: syntax error, unexpected '}', expecting ',' or ';'\n", code)),
              "toyhost: /toy/image.glsl:1:78: error: Image: ';' missing here, before the '}' that closes the block "
              "(syntax error, unexpected '}', expecting ',' or ';') [shader.compile]\n"
              "    1 | void mainImage(out vec4 fragColor, in vec2 fragCoord) { fragColor = vec4(1.0) }\n"
              "      |                                                                              ^");
}

TEST(CompileMessages, AMacroThatExpandsToItselfIsSaidToReferToItself) {
    const std::string code = "#define LOOP_A LOOP_A\n"
                             "void mainImage(out vec4 fragColor, in vec2 fragCoord) { float x = LOOP_A; fragColor = vec4(x); }\n";
    const std::vector<Diagnostic> problems =
        explain("0:2(67): error: `LOOP_A' undeclared\n0:2(92): warning: `x' used uninitialized\n", code);
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_EQ(problems[0].message,
              "`LOOP_A' undeclared (the macro `LOOP_A' defined on line 1 refers to itself: the preprocessor leaves a "
              "macro's own name in its expansion, so the compiler meets `LOOP_A' as a name nothing declares)");
    // Through another macro.
    const std::string twoMacros = "#define A B\n#define B A\n"
                                  "void mainImage(out vec4 fragColor, in vec2 fragCoord) { float x = A; fragColor = vec4(x); }\n";
    const std::vector<Diagnostic> cycle =
        explain("0:3(67): error: `A' undeclared\n0:3(87): warning: `x' used uninitialized\n", twoMacros);
    ASSERT_EQ(cycle.size(), 1u);
    EXPECT_NE(cycle[0].message.find("the macro `A' defined on line 1 refers to itself through `B'"), std::string::npos)
        << cycle[0].message;
}

// A misspelt macro is never offered the local variable that only matches with case ignored; a
// misspelt variable is offered the variable, not the macro.
TEST(CompileMessages, MacroNamesAndVariablesAreSuggestedEachForTheirOwnKind) {
    const std::string misspeltMacro = "#define LOOP_COUNT 4\n"
                                      "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                      "    float loop_cnt = 2.0;\n"
                                      "    float x = loop_cnt * float(LOOP_CNT);\n"
                                      "    fragColor = vec4(x);\n"
                                      "}\n";
    const std::vector<Diagnostic> macro = explain("0:4(29): error: `LOOP_CNT' undeclared\n"
                                                  "0:4(23): error: cannot construct `float' from a non-numeric data type\n"
                                                  "0:4(12): error: operands to arithmetic operators must be numeric\n"
                                                  "0:5(19): warning: `x' used uninitialized\n",
                                                  misspeltMacro);
    ASSERT_EQ(macro.size(), 1u);
    EXPECT_EQ(macro[0].message, "`LOOP_CNT' undeclared (did you mean `LOOP_COUNT'?)");
    const std::string misspeltVariable = "#define LOOP_CNT 4\n"
                                         "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                                         "    float loop_count = 2.0;\n"
                                         "    float x = loop_cnt * float(LOOP_CNT);\n"
                                         "    fragColor = vec4(x);\n"
                                         "}\n";
    const std::vector<Diagnostic> variable = explain("0:4(12): error: `loop_cnt' undeclared\n"
                                                     "0:4(12): error: operands to arithmetic operators must be numeric\n"
                                                     "0:5(19): warning: `x' used uninitialized\n",
                                                     misspeltVariable);
    ASSERT_EQ(variable.size(), 1u);
    EXPECT_EQ(variable[0].message, "`loop_cnt' undeclared (did you mean `loop_count'?)");
}

// docs/running.md: errors that only follow from an earlier one are left out. A swizzle a vector
// does not have makes the constructor around it fail twice more.
TEST(CompileMessages, AWrongSwizzleIsOneErrorWithoutItsFollowOns) {
    const std::string code = "void mainImage(out vec4 fragColor, in vec2 fragCoord) {\n"
                             "  vec2 a = fragCoord;\n"
                             "  vec4 c = vec4(a.xyz, 1.0);\n"
                             "  fragColor = c * 2.0;\n"
                             "  float k = c.x + c.y;\n"
                             "  fragColor += vec4(k);\n"
                             "}\n";
    const std::vector<Diagnostic> problems = explain("0:3(16): error: invalid swizzle / mask `xyz'\n"
                                                     "0:3(16): error: type mismatch\n"
                                                     "0:3(11): error: cannot construct `vec4' from a non-numeric data type\n"
                                                     "0:4(14): warning: `c' used uninitialized\n"
                                                     "0:5(12): warning: `c' used uninitialized\n"
                                                     "0:5(18): warning: `c' used uninitialized\n",
                                                     code);
    ASSERT_EQ(problems.size(), 1u) << text(problems);
    EXPECT_EQ(problems[0].message, "invalid swizzle / mask `xyz'");
    EXPECT_EQ(problems[0].line, 3);
}
