// The WebGL source rewrite is never switched off silently (issue 42): a `const` that calls asin or
// acos keeps every rule (the precise versions are user functions, not constant expressions), a rule
// whose text the driver refuses is skipped alone with a [shader.rule-skipped] warning naming it, a
// local declared after a comma shadows a constant in the integer fold, zero-initialisation reaches
// structs defined in a function and for-init declarations, and an unknown directive in a skipped
// group is ignored as the browser ignores it; an index in a macro body is clamped, a local declared
// by a macro zeroed, constant int vectors, macro operands and float built-ins folded as ANGLE folds
// them. Expected values are the browser's (issue 42's
// measurements with ../shared/webref); Mesa alone gives the other value named in each comment.
#include "GlTestSupport.h"

#include <optional>

#include "player/PlayerDesc.h"
#include "shader/ShaderAssembly.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

class RewriteRules : public GlTest {
protected:
    struct Rendered {
        std::vector<float> pixels;  // RGBA32F, 4x4, bottom row first
        std::vector<Diagnostic> notices;
        std::string error;  // the player's error when it did not compile
    };

    // The first frame of a one-Image shadertoy of `code` at 4x4 in RGBA32F; with `planted`, that
    // rule of the rewrite is made to fail (GlslRewriteOptions::plantedFailure).
    Rendered render(const std::string& name, const std::string& code, std::optional<RewriteRule> planted = {}) {
        const fs::path dir = freshOutputDir("rewrite_rules/" + name);
        writeFile(dir / "image.glsl", code);
        writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
        Rendered out;
        auto manifest = loadShadertoy(dir);
        if (!manifest) {
            out.error = manifest.error().text();
            return out;
        }
        auto plan = planPlayer(std::move(*manifest), MediaOptions{});
        if (!plan) {
            out.error = plan.error().text();
            return out;
        }
        if (planted) {
            PassSource& source = plan->sources.at(0);
            source.parts.options.plantedFailure = planted;
            source.text = rewrittenShader(source.parts, source.parts.options);
        }
        PlayerDesc desc;
        desc.width = 4;
        desc.height = 4;
        desc.floatImage = true;
        auto player = Player::create(context_, std::move(*plan), desc);
        if (!player) {
            out.error = player.error().text();
            return out;
        }
        (*player)->step(fixedStep(0));
        (*player)->readRgba32f(PassId::Image, out.pixels);
        out.notices = (*player)->compileNotices();
        return out;
    }

    // Channel `c` of pixel (x, 0).
    static float at(const Rendered& r, int x, int c) { return r.pixels.at(static_cast<std::size_t>(x) * 4 + c); }
};

// One shader that shows a value of each rule, pixel column 0: the per-call accumulator (4 calls of
// 0.125 from zero: 0.5; Mesa 1.25), the sum of a float[4] read with i <= 4 (clamped: 14; Mesa 0), an
// uninitialised global vec4's x (0; llvmpipe NaN) as 0.25 when zero; column 1: 7 / 0 folded (INT_MAX
// >> 16: 32767; Mesa 0), asin(0.9) as precise as the browser's (|error| < 1e-5; Mesa's is 3.5e-4
// off), a variable named `packed` (0.75; Mesa refuses the name); column 2: round(2.5) folded half
// away from zero (3; Mesa 2).
const char* kEveryRule =
    "float acc(float x) { float t; t += x; return t; }\n"
    "vec4 g;\n"
    "const int Z = 0;\n"
    "void mainImage(out vec4 o, in vec2 f) {\n"
    "    float s = 0.0; for (int i = 0; i < 4; i++) s += acc(0.125);\n"
    "    float a[4] = float[4](1.0, 2.0, 3.0, 4.0); float sum = 0.0;\n"
    "    for (int i = 0; i <= 4 + int(iTime); i++) sum += a[i];\n"
    "    float packed = 0.75;\n"
    "    float e = abs(asin(0.9 + iTime) - 1.11976951) < 1e-5 ? 1.0 : 0.0;\n"
    "    if (f.x < 1.0) o = vec4(s, sum, g.x == 0.0 ? 0.25 : 1.0, 1.0);\n"
    "    else if (f.x < 2.0) o = vec4(float((7 / Z) >> 16), e, packed, 1.0);\n"
    "    else o = vec4(round(2.5), 0.0, 0.0, 1.0);\n"
    "}\n";

void expectEveryRule(const std::vector<float>& pixels) {
    ASSERT_EQ(pixels.size(), 64u);
    EXPECT_EQ(pixels[0], 0.5f) << "zero-init";
    EXPECT_EQ(pixels[1], 14.0f) << "index clamp";
    EXPECT_EQ(pixels[2], 0.25f) << "global zero";
    EXPECT_EQ(pixels[4], 32767.0f) << "integer fold";
    EXPECT_EQ(pixels[5], 1.0f) << "precise acos";
    EXPECT_EQ(pixels[6], 0.75f) << "packed renamed";
    EXPECT_EQ(pixels[8], 3.0f) << "float fold";
}

TEST_F(RewriteRules, EveryRuleAppliesWithoutAWarning) {
    const Rendered r = render("every_rule", kEveryRule);
    ASSERT_EQ(r.error, "");
    expectEveryRule(r.pixels);
    EXPECT_TRUE(r.notices.empty()) << formatDiagnostics(r.notices);
}

// Issue 42: `const float PI = acos(-1.0);` (0.67% of public shaders) made the rewritten text one the
// driver refuses (toyhost_acos is no constant expression) and switched every rule off silently.
// A literal's asin/acos is written as ANGLE folds it (acosf(-1) = 3.14159274); any other constant
// call is the driver's.
TEST_F(RewriteRules, AConstAcosKeepsEveryRule) {
    const std::string code = std::string("const float PI = acos(-1.0);\nconst float Q = asin(sin(0.5)) * 2.0;\n"
                                         "#define HALF asin(1.0)\nconst float H = HALF;\nfloat arr[int(acos(-1.0))];\n") +
                             kEveryRule;
    const Rendered r = render("const_acos", code + "\n");
    ASSERT_EQ(r.error, "");
    expectEveryRule(r.pixels);
    EXPECT_TRUE(r.notices.empty()) << formatDiagnostics(r.notices);
    const Rendered pi = render("const_acos_value",
                               "const float PI = acos(-1.0);\nconst float Q = asin(sin(0.5)) * 2.0;\n"
                               "void mainImage(out vec4 o, in vec2 f) { float k[int(PI)]; o = vec4(PI, Q, float(k.length()), 1.0); }\n");
    ASSERT_EQ(pi.error, "");
    EXPECT_EQ(at(pi, 0, 0), 3.14159274f);
    EXPECT_NEAR(at(pi, 0, 1), 1.0f, 2e-3);
    EXPECT_EQ(at(pi, 0, 2), 3.0f);
}

// A rule whose text the driver refuses is skipped alone: each rule is made to fail in turn
// (GlslRewriteOptions::plantedFailure); the others' effects stay visible and the warning names it.
TEST_F(RewriteRules, ARefusedRuleIsSkippedAloneWithAWarning) {
    for (RewriteRule rule : kRewriteRules) {
        SCOPED_TRACE(rewriteRuleName(rule));
        // Without `packed` when the rename is the one that fails: Mesa refuses the name.
        std::string code = kEveryRule;
        if (rule == RewriteRule::Rename) code.replace(code.find("float packed"), 12, "float pecked"),
                                         code.replace(code.find(", packed,"), 9, ", pecked,");
        const Rendered r = render(std::string("planted_") + rewriteRuleName(rule), code, rule);
        ASSERT_EQ(r.error, "");
        ASSERT_EQ(r.pixels.size(), 64u);
        // Without zeroInit the accumulator and the global are undefined (llvmpipe drew anything).
        if (rule != RewriteRule::ZeroInit) EXPECT_EQ(r.pixels[0], 0.5f);
        if (rule != RewriteRule::ClampIndices) EXPECT_EQ(r.pixels[1], 14.0f);
        if (rule != RewriteRule::ZeroInit) EXPECT_EQ(r.pixels[2], 0.25f);
        if (rule != RewriteRule::FoldIntegerConstants) EXPECT_EQ(r.pixels[4], 32767.0f);
        EXPECT_EQ(r.pixels[5], rule == RewriteRule::PreciseInverseTrig ? 0.0f : 1.0f);
        EXPECT_EQ(r.pixels[6], 0.75f);
        EXPECT_EQ(r.pixels[8], rule == RewriteRule::FoldFloatConstants ? 2.0f : 3.0f);
        ASSERT_EQ(r.notices.size(), 1u) << formatDiagnostics(r.notices);
        const Diagnostic& warning = r.notices[0];
        EXPECT_EQ(warning.severity, Severity::Warning);
        EXPECT_EQ(warning.code, Code::ShaderRuleSkipped);
        EXPECT_EQ(warning.line, 14);  // the planted statement, after the text's last line
        EXPECT_NE(warning.message.find(std::string("'") + rewriteRuleName(rule) + "'"), std::string::npos) << warning.message;
        EXPECT_NE(warning.message.find("toyhost_planted_failure_of_"), std::string::npos) << "the driver's words: " << warning.message;
        EXPECT_NE(formatDiagnostic(warning).find("[shader.rule-skipped]"), std::string::npos);
    }
}

// A shader with an error of its own still reports it, and blames no rule.
TEST_F(RewriteRules, AUsersOwnErrorBlamesNoRule) {
    const Rendered r = render("own_error", "void mainImage(out vec4 o, in vec2 f) { float t; o = vec4(t + undefinedThing); }\n");
    EXPECT_NE(r.error.find("undefinedThing"), std::string::npos) << r.error;
    EXPECT_EQ(r.error.find("rule-skipped"), std::string::npos) << r.error;
}

// A local declared after a comma (also in a for-init) shadows the global constant in the fold:
// 7 / ZC with the local ZC = 2 is 3 (Mesa's fold of the global's 0: 2147483647), 7 % MN 1
// (2147483647), 1 << SS 4 (0).
TEST_F(RewriteRules, ALocalAfterACommaShadowsAConstant) {
    const Rendered r = render("comma_shadow",
                              "const int ZC = 0;\nconst int MN = 0;\nconst int SS = 40;\n"
                              "void mainImage(out vec4 o, in vec2 f) {\n"
                              "    int a = 2, ZC = 2;\n"
                              "    int m = 0;\n"
                              "    for (int b = 0, MN = 3; b < 1; b++) m = 7 % MN;\n"
                              "    int c = 1, SS = 2;\n"
                              "    o = vec4(float(7 / ZC), float(m), float(1 << SS), float(a + c));\n"
                              "}\n");
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(at(r, 0, 0), 3.0f);
    EXPECT_EQ(at(r, 0, 1), 1.0f);
    EXPECT_EQ(at(r, 0, 2), 4.0f);
}

// Zero-initialisation of a struct defined inside the function (3 calls of `L l; l.a += 1.0;`: 3;
// Mesa 6) and of an uninitialised for-init (`for (float t; t < 1.0; t += 0.5)` in 3 calls: 6; Mesa 2).
TEST_F(RewriteRules, LocalStructsAndForInitsAreZeroAtEveryCall) {
    const Rendered r = render("zero_forms",
                              "float one() { struct L { float a; vec2 b; }; L l; l.a += 1.0; l.b += 1.0; return l.a + l.b.x - 1.0; }\n"
                              "float steps() { float s = 0.0; for (float t; t < 1.0; t += 0.5) s += 1.0; return s; }\n"
                              "void mainImage(out vec4 o, in vec2 f) {\n"
                              "    float a = 0.0, b = 0.0;\n"
                              "    for (int i = 0; i < 3; i++) { a += one(); b += steps(); }\n"
                              "    o = vec4(a, b, 0.0, 1.0);\n"
                              "}\n");
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(at(r, 0, 0), 3.0f);
    EXPECT_EQ(at(r, 0, 1), 6.0f);
}

// `#elseif` (a typo of `#elif`) in a skipped group: the browser reads only conditional directives
// there and takes the `#else` (0.6); Mesa's preprocessor stopped with "syntax error, unexpected
// IDENTIFIER, expecting NEWLINE". In a group that is not skipped the browser refuses it, and so
// does toyhost.
TEST_F(RewriteRules, AnUnknownDirectiveInASkippedGroupIsIgnored) {
    const Rendered r = render("elseif_skipped",
                              "#if 0\n#define V 0.2\n#elseif 1\n#define V 0.4\n#else\n#define V 0.6\n#endif\n"
                              "void mainImage(out vec4 o, in vec2 f) { o = vec4(V, 0.0, 0.0, 1.0); }\n");
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(at(r, 0, 0), 0.6f);
    const Rendered active = render("elseif_active",
                                   "#if 1\n#define V 0.2\n#elseif 1\n#define V 0.4\n#endif\n"
                                   "void mainImage(out vec4 o, in vec2 f) { o = vec4(V, 0.0, 0.0, 1.0); }\n");
    EXPECT_NE(active.error.find("image.glsl:3"), std::string::npos) << active.error;
    EXPECT_NE(active.error.find("elseif"), std::string::npos) << active.error;
}

// The value of `pick`'s cell (pixel x of the bottom row, channel c) in a shader that writes cell
// (x, c) of 4 x 3 values: `values` is GLSL for a `float v[12]` initialiser's elements.
std::string cells(const std::string& before, const std::string& values) {
    return before + "void mainImage(out vec4 o, in vec2 f) {\n    float v[12] = float[12](" + values +
           ");\n    int x = int(f.x);\n    o = vec4(v[3 * x], v[3 * x + 1], v[3 * x + 2], 1.0);\n}\n";
}

// Issue 42: an index written in a `#define` body is clamped as the browser clamps the expanded
// text: `AT(k)` with k = 4 on `const float PAL[4]` is PAL[3] (4.0; Mesa read the next array's
// first element, 11.0); a matrix column through a macro likewise.
TEST_F(RewriteRules, AnIndexInAMacroBodyIsClamped) {
    const Rendered r = render("macro_index", cells("#define AT(i) PAL[i]\n#define COL(i) MAT[i]\n"
                                                   "const float PAL[4] = float[4](1.0, 2.0, 3.0, 4.0);\n"
                                                   "const float NEXT[4] = float[4](11.0, 12.0, 13.0, 14.0);\n"
                                                   "const mat2 MAT = mat2(1.0, 2.0, 3.0, 4.0);\n",
                                                   "AT(4 + int(iTime)), AT(-1 + int(iTime)), NEXT[int(iTime)], "
                                                   "COL(2 + int(iTime)).y, 0.,0.,0.,0.,0.,0.,0.,0."));
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(at(r, 0, 0), 4.0f);
    EXPECT_EQ(at(r, 0, 1), 1.0f);
    EXPECT_EQ(at(r, 0, 2), 11.0f);
    EXPECT_EQ(at(r, 1, 0), 4.0f);
    EXPECT_TRUE(r.notices.empty()) << formatDiagnostics(r.notices);
}

// Issue 42: a local declared by a macro is zero at every execution of its declaration, as the
// browser zeroes the expanded text: 3 calls of `ACC acc += 1.0;` sum to 3 (Mesa 6), also for a
// function-like macro and an array.
TEST_F(RewriteRules, ALocalDeclaredByAMacroIsZeroAtEveryCall) {
    const Rendered r = render("macro_declaration",
                              "#define ACC float acc;\n#define LOCAL(t, n) t n\n"
                              "float one() { ACC acc += 1.0; return acc; }\n"
                              "float two() { LOCAL(vec2, p), q[2]; p += 1.0; q[1] += 1.0; return p.y + q[1].x; }\n"
                              "void mainImage(out vec4 o, in vec2 f) {\n"
                              "    float a = 0.0, b = 0.0;\n"
                              "    for (int i = 0; i < 3; i++) { a += one(); b += two(); }\n"
                              "    o = vec4(a, b, 0.0, 1.0);\n"
                              "}\n");
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(at(r, 0, 0), 3.0f);
    EXPECT_EQ(at(r, 0, 1), 6.0f);
    EXPECT_TRUE(r.notices.empty()) << formatDiagnostics(r.notices);
}

// Issue 42: ANGLE folds operations on constant vectors and on constants written as macros, giving
// the undefined ones its own values (browser / Mesa): ivec2(7)/0, ivec2(7)%0, CV.x/CV.y with
// CV = ivec2(7,0) INT_MAX / 0 (shown >> 16: 32767), uvec2(7u)/0u UINT_MAX / 0 (>> 16: 65535),
// ivec2(-7)%3 0 / -1, ivec2(1)<<33 0 / 2, ivec2(-8)>>40 0 / -1; with #define Z 0: 7/Z, 7%Z,
// const int QZ = 7/Z INT_MAX / 0, 7u/uint(Z) UINT_MAX / 0.
TEST_F(RewriteRules, ConstantVectorsAndMacroOperandsAreFoldedAsTheBrowserFoldsThem) {
    const Rendered r = render("vector_fold",
                              cells("#define Z 0\nconst ivec2 CV = ivec2(7,0);\nconst int QZ = 7/Z;\n",
                                    "float((ivec2(7)/0).x >> 16), float((ivec2(7)%0).y >> 16), float(CV.x/CV.y >> 16),\n"
                                    "        float((uvec2(7u)/0u).x >> 16u), float((ivec2(-7)%3).x), float((ivec2(1)<<33).y),\n"
                                    "        float((ivec2(-8)>>40).x), float(7/Z >> 16), float(7%Z >> 16),\n"
                                    "        float(QZ >> 16), float(7u/uint(Z) >> 16u), 0.0"));
    ASSERT_EQ(r.error, "");
    const float expected[12] = {32767, 32767, 32767, 65535, 0, 0, 0, 32767, 32767, 32767, 65535, 0};
    for (int i = 0; i < 12; ++i) EXPECT_EQ(at(r, i / 3, i % 3), expected[i]) << "cell " << i;
}

// Issue 42: ANGLE folds a float built-in whose constant arguments GLSL leaves undefined to 0, and a
// constant round() half away from zero (browser / Mesa): log(-1.), sqrt(-1.), inversesqrt(-1.),
// pow(-8., 1./3.), normalize(vec3(0)).x, acosh(.5) 0 / NaN; log(0.), log2(0.) 0 / -inf;
// inversesqrt(0.), pow(0.,-1.), atanh(1.) 0 / +inf; pow(0.,0.) 0 / 1; atan(0.,-0.) 0 / pi; round(2.5)
// as an expression, a const, through a macro and round(float(5)/2.0) 3 / 2; round(vec2(.5,-2.5))
// (1,-3) / (0,-2); round(-.5) -1 / -0; round(4.5) 5 / 4. At run time both sides round half to even.
TEST_F(RewriteRules, FloatBuiltInsAreFoldedAsTheBrowserFoldsThem) {
    const Rendered undefined = render("float_fold_undefined",
                                      cells("", "log(-1.), sqrt(-1.), inversesqrt(-1.), pow(-8., 1./3.), normalize(vec3(0)).x,\n"
                                                "        acosh(.5), log(0.), log2(0.), inversesqrt(0.), pow(0.,-1.), atanh(1.),\n"
                                                "        pow(0.,0.) + atan(0.,-0.)"));
    ASSERT_EQ(undefined.error, "");
    for (int i = 0; i < 12; ++i) EXPECT_EQ(at(undefined, i / 3, i % 3), 0.0f) << "cell " << i;
    const Rendered rounded = render("float_fold_round",
                                    cells("const float R = round(2.5);\n#define HALF round(2.5)\n#define RND(x) round(x)\n",
                                          "round(2.5), R, HALF, RND(2.5), round(float(5)/2.0), round(vec2(.5,-2.5)).x,\n"
                                          "        round(vec2(.5,-2.5)).y, round(-.5), round(2.5 + iTime), round(4.5),\n"
                                          "        round(3.5), 0.0"));
    ASSERT_EQ(rounded.error, "");
    const float expected[12] = {3, 3, 3, 3, 3, 1, -3, -1, 2, 5, 4, 0};
    for (int i = 0; i < 12; ++i) EXPECT_EQ(at(rounded, i / 3, i % 3), expected[i]) << "cell " << i;
    EXPECT_TRUE(rounded.notices.empty()) << formatDiagnostics(rounded.notices);
}

}  // namespace
}  // namespace toyhost::testing
