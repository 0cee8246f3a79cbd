// OpaqueDivisors (through GlslRewrite): every divisor inside a function body passes through
// toyhost_opaque (its bits XORed with a uniform 0), so Mesa 22.3 cannot fold a division by a zero it sees
// (it folded those from uninitialised memory: 0, NaN or random values, different on every run;
// the browser's GPU computes IEEE +-inf/NaN at run time). Constant expressions, array sizes and
// indices, case labels, non-zero literals and integer literals are left alone, on the same lines.
#include <gtest/gtest.h>

#include <string>

#include "shader/GlslRewrite.h"
#include "shader/OpaqueDivisors.h"

using namespace toyhost;

namespace {

std::string opaqueOnly(const std::string& text) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = options.foldIntegerConstants = false;
    options.preciseInverseTrig = options.foldFloatConstants = false;
    return rewriteLikeWebGL(text, options);
}

}  // namespace

TEST(OpaqueDivisors, TheRightOperandOfADivisionIsOpaque) {
    EXPECT_EQ(opaqueOnly("float f(float a, float b) { return a / (b - b) + a/0.0 + a / b.x * 2.0 + a / -g(b)[1]; }"),
              "float f(float a, float b) { return a / toyhost_opaque((b - b)) + a/toyhost_opaque(0.0) + "
              "a / toyhost_opaque(b.x) * 2.0 + a / toyhost_opaque(-g(b)[1]); }");
    EXPECT_EQ(opaqueOnly("void f() { v = a / b++ + c / float[2](1., 2.)[i] + d / s.v.length(); }"),
              "void f() { v = a / toyhost_opaque(b++) + c / toyhost_opaque(float[2](1., 2.)[i]) + "
              "d / toyhost_opaque(s.v.length()); }");
}

TEST(OpaqueDivisors, DivideAssignHidesItsWholeRightHandSide) {
    EXPECT_EQ(opaqueOnly("void f() { x /= a - a; for (int i = 0; i < 2; i++) y /= b * 0.0, z = 1.0; }"),
              "void f() { x /= toyhost_opaque(a - a); for (int i = 0; i < 2; i++) y /= toyhost_opaque(b * 0.0), z = 1.0; }");
}

TEST(OpaqueDivisors, SmoothstepsSecondEdgeAndModsDivisor) {
    EXPECT_EQ(opaqueOnly("float f(float x) { return smoothstep(0.5, 0.5, x) + mod(x, 0.0) + mod(x, 2.0) + v.mod(x, y); }"),
              "float f(float x) { return smoothstep(0.5, toyhost_opaque(0.5), x) + mod(x, toyhost_opaque(0.0)) + "
              "mod(x, 2.0) + v.mod(x, y); }");
    EXPECT_EQ(opaqueOnly("float f(float x) { return smoothstep(0.0, 1.0, x) + smoothstep(-1., 1., x); }"),
              "float f(float x) { return smoothstep(0.0, 1.0, x) + smoothstep(-1., 1., x); }");
    EXPECT_EQ(opaqueOnly("void f() { c = smoothstep(e, g(e, 1.0), vec2(x)); }"),
              "void f() { c = smoothstep(e, toyhost_opaque(g(e, 1.0)), vec2(x)); }");
}

TEST(OpaqueDivisors, TheOtherBuiltInsThatDivideByAnArgument) {
    EXPECT_EQ(opaqueOnly("void f() { a = atan(y, 0.0) + atan(y / 2.0) + atanh(1.0); m = inverse(mat2(0.0)); }"),
              "void f() { a = atan(y, toyhost_opaque(0.0)) + atan(y / 2.0) + atanh(toyhost_opaque(1.0)); "
              "m = inverse(toyhost_opaque(mat2(0.0))); }");
}

TEST(OpaqueDivisors, ConstantExpressionsStayConstant) {
    const std::string untouched =
        "const float K = 1.0 / 0.0;\nfloat g = 2.0 / 0.0;\n"
        "float f(const float x) {\n  const float L = x0 / 0.0, M = a ? b : c / d;\n  float a[int(8.0 / 2.0)];\n"
        "  switch (i) { case 4 / 2: break; }\n  return a[int(x / y)] + x / 2.0 + x / 1e-3 + float(i / 2) + x / -3.5;\n}\n"
        "#define INV(x) (1.0 / (x))\n";
    EXPECT_EQ(opaqueOnly(untouched), untouched);
    // After a `const` statement and a case label, the next division is the user's again.
    EXPECT_EQ(opaqueOnly("float f() { const float L = 1.0 / 0.0; float m = L / L; switch (i) { case 1: m /= 0.0; } return m; }"),
              "float f() { const float L = 1.0 / 0.0; float m = L / toyhost_opaque(L); switch (i) { case 1: m /= "
              "toyhost_opaque(0.0); } return m; }");
}

TEST(OpaqueDivisors, LinesAreKept) {
    const std::string out = opaqueOnly("float f(float a) {\n  return a /\n    (a - a);\n}\n");
    EXPECT_EQ(out, "float f(float a) {\n  return a /\n    toyhost_opaque((a - a));\n}\n");
}

TEST(OpaqueDivisors, IntegerConstantsAreLeftToTheIntegerFold) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = false;
    EXPECT_EQ(rewriteLikeWebGL("int f(int i) { return 7 / 0 + i / (i - i); }", options),
              "int f(int i) { return 2147483647 + i / toyhost_opaque((i - i)); }");
}

TEST(OpaqueDivisors, OpeningGoesBeforeAndClosingAfterTheOtherRulesInsertions) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.foldIntegerConstants = false;
    EXPECT_EQ(rewriteLikeWebGL("float f(float x, int i) { float a[2]; return x / asin(x) + x / a[i]; }", options),
              "float f(float x, int i) { float a[2]; return x / toyhost_opaque(toyhost_asin(x)) + "
              "x / toyhost_opaque(a[int(clamp(float(i),0.0,1.0))]); }");
}

TEST(OpaqueDivisors, TheHeaderDeclaresTheUniformAndOverloadsOnlyWhenUsed) {
    EXPECT_EQ(opaqueDivisorDeclarations("float f(float x) { return x / 2.0; }"), "");
    const std::string declarations = opaqueDivisorDeclarations("float f(float x) { return 1.0 / x; }");
    EXPECT_NE(declarations.find("uniform uint toyhost_zero;\n"), std::string::npos);
    EXPECT_NE(declarations.find("vec3 toyhost_opaque(vec3 x) { return uintBitsToFloat(floatBitsToUint(x) ^ toyhost_zero); }"),
              std::string::npos);
    EXPECT_NE(declarations.find("mat4x3 toyhost_opaque(mat4x3 x) { return mat4x3(toyhost_opaque(x[0]), toyhost_opaque(x[1]), "
                                "toyhost_opaque(x[2]), toyhost_opaque(x[3])); }"),
              std::string::npos);
    EXPECT_NE(declarations.find("uvec2 toyhost_opaque(uvec2 x) { return x; }"), std::string::npos);
}
