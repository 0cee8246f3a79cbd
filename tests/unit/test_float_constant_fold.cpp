// FloatConstantFold (through GlslRewrite): a float built-in call on constants whose value ANGLE's
// folder decides itself (0 for arguments GLSL leaves undefined, round() half away from zero) is
// written as that value, in code, in `#define` bodies and in place of a macro that is such a call;
// every call ANGLE folds as Mesa does, and every call on a non-constant, is left to the driver.
#include <gtest/gtest.h>

#include <string>

#include "shader/GlslRewrite.h"

using namespace toyhost;

namespace {

std::string foldOnly(const std::string& text) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = options.opaqueDivisors = options.foldIntegerConstants = false;
    options.preciseInverseTrig = false;
    return rewriteLikeWebGL(text, options);
}

}  // namespace

TEST(FloatConstantFold, UndefinedArgumentsGiveZero) {
    EXPECT_EQ(foldOnly("float a = log(-1.) + sqrt(-1.) + inversesqrt(-1.) + pow(-8., 1./3.) + acosh(.5);"),
              "float a = 0.0 + 0.0 + 0.0 + 0.0 + 0.0;");
    EXPECT_EQ(foldOnly("float b = log(0.) + log2(0.) + inversesqrt(0.) + pow(0.,-1.) + atanh(1.) + pow(0.,0.) + atan(0.,-0.);"),
              "float b = 0.0 + 0.0 + 0.0 + 0.0 + 0.0 + 0.0 + 0.0;");
    EXPECT_EQ(foldOnly("float n = normalize(vec3(0)).x;"), "float n = vec3(0.0, 0.0, 0.0).x;");
    EXPECT_EQ(foldOnly("float s = smoothstep(1.0, 1.0, 0.5) + clamp(0.5, 2.0, 1.0);"), "float s = 0.0 + 0.0;");
}

TEST(FloatConstantFold, RoundIsHalfAwayFromZero) {
    EXPECT_EQ(foldOnly("const float R = round(2.5);\nfloat m = round(float(5)/2.0) + round(-.5);"),
              "const float R = 3.0;\nfloat m = 3.0 + (-1.0);");
    EXPECT_EQ(foldOnly("vec2 v = round(vec2(.5,-2.5));"), "vec2 v = vec2(1.0, (-3.0));");
    // Through macros: a constant operand, a body that is the call, a function-like macro that is it.
    EXPECT_EQ(foldOnly("#define HALF 2.5\n#define R round(2.5)\n#define RR(x) (round(x))\nfloat a = round(HALF) + R + RR(2.5);"),
              "#define HALF 2.5\n#define R 3.0\n#define RR(x) (round(x))\nfloat a = 3.0 + R + 3.0;");
    // Constants declared once, also vectors and their swizzles.
    EXPECT_EQ(foldOnly("const vec2 H = vec2(0.5, 1.5);\nfloat a = round(H.x) + round(H).y;"),
              "const vec2 H = vec2(0.5, 1.5);\nfloat a = 1.0 + vec2(1.0, 2.0).y;");
}

TEST(FloatConstantFold, WhatMesaFoldsAlikeAndNonConstantsAreLeftAlone) {
    const std::string same = "float a = log(2.0) + round(2.4) + round(3.5) + sqrt(4.0) + pow(2.0, 3.0);";
    EXPECT_EQ(foldOnly(same), same);
    const std::string runtime = "uniform float u; float f(float x) { float y = 2.0; return log(x) + round(u) + sqrt(-y) + log(-1.0 + x); }";
    EXPECT_EQ(foldOnly(runtime), runtime);
    // A macro's parameter is never a constant; a name declared twice may be shadowed.
    const std::string shadowed = "#define L(x) log(x)\nconst float Z = 0.0;\nvoid f() { float Z = 1.0; float a = log(Z); }";
    EXPECT_EQ(foldOnly(shadowed), shadowed);
    // Infinite values are never written; asin and acos are preciseInverseTrig's.
    const std::string other = "float a = round(vec2(0.5, 1e39)).x + asin(2.0);";
    EXPECT_EQ(foldOnly(other), other);
}

TEST(FloatConstantFold, EveryLineStaysWhereItWas) {
    EXPECT_EQ(foldOnly("float a = log(\n-1.0\n);"), "float a = 0.0\n\n;");
    const std::string directive = "#define A log(\\\n-1.0)\nfloat b = A;";
    EXPECT_EQ(foldOnly(directive), directive);
}
