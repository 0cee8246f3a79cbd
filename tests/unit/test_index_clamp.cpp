// IndexClamp (through GlslRewrite): dynamic indices of arrays, vectors and matrices are clamped as
// ANGLE's ClampIndirectIndices does (int(clamp(float(i), 0.0, float(n - 1)))), on the same line;
// literal indices, array sizes in declarations and what the rewrite cannot type are left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "shader/GlslRewrite.h"

using namespace toyhost;

namespace {

std::string clampOnly(const std::string& text) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = false;
    return rewriteLikeWebGL(text, options);
}

}  // namespace

TEST(IndexClamp, ArrayIndexInALoopIsClampedToTheDeclaredSize) {
    EXPECT_EQ(clampOnly("float s(int n){ float a[4] = float[4](1.,2.,3.,4.); float t = 0.;\n"
                        "for (int i = 0; i <= n; i++) t += a[i]; return t; }"),
              "float s(int n){ float a[4] = float[4](1.,2.,3.,4.); float t = 0.;\n"
              "for (int i = 0; i <= n; i++) t += a[int(clamp(float(i),0.0,3.0))]; return t; }");
}

TEST(IndexClamp, VectorsMatricesAndTheirColumns) {
    EXPECT_EQ(clampOnly("float f(vec4 v, mat3x2 m, int i){ return v[i] + m[i][i+1]; }"),
              "float f(vec4 v, mat3x2 m, int i){ return v[int(clamp(float(i),0.0,3.0))] + "
              "m[int(clamp(float(i),0.0,2.0))][int(clamp(float(i+1),0.0,1.0))]; }");
}

TEST(IndexClamp, ArraysWithoutALiteralSizeUseLength) {
    EXPECT_EQ(clampOnly("const int N = 3; vec3 P[N]; float g(int i){ return P[i].x; }"),
              "const int N = 3; vec3 P[N]; float g(int i){ return P[int(clamp(float(i),0.0,float(P.length()-1)))].x; }");
}

TEST(IndexClamp, UniformArraysNestedIndicesAndWrites) {
    EXPECT_EQ(clampOnly("void h(int i){ int b[2]; float c[3]; c[b[i]] = iChannelResolution[i].x; }"),
              "void h(int i){ int b[2]; float c[3]; c[int(clamp(float(b[int(clamp(float(i),0.0,1.0))]),0.0,2.0))] = "
              "iChannelResolution[int(clamp(float(i),0.0,3.0))].x; }");
}

TEST(IndexClamp, LiteralIndicesDeclarationsAndUntypedExpressionsAreLeftAlone) {
    const std::string text =
        "struct S { float v[2]; }; float k(int i, S s){ float a[3], b[2]; vec2 w = vec2(1.);\n"
        "  return a[1] + b[0] + s.v[i] + w.yx[i] + float[2](1., 2.)[1]; }";
    EXPECT_EQ(clampOnly(text), text);
}

TEST(IndexClamp, ANameShadowedByALaterDeclarationUsesTheNewType) {
    EXPECT_EQ(clampOnly("vec4 v; float f(int i){ float v[2]; return v[i]; }"),
              "vec4 v; float f(int i){ float v[2]; return v[int(clamp(float(i),0.0,1.0))]; }");
}

TEST(IndexClamp, IndicesSpanningLinesKeepEveryLineWhereItWas) {
    const std::string text = "float f(float a[4], int i){ return a[i\n + 1]; }\n";
    const std::string out = clampOnly(text);
    EXPECT_EQ(out, "float f(float a[4], int i){ return a[int(clamp(float(i\n + 1),0.0,3.0))]; }\n");
    EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), std::count(text.begin(), text.end(), '\n'));
}

// Issue 42: ANGLE clamps the text after preprocessing, so an index written in a macro body is
// clamped at every use: it is clamped in the body, typed by the text's declarations (a parameter is
// an index like any other, never a name to type).
TEST(IndexClamp, AnIndexInAMacroBodyIsClamped) {
    EXPECT_EQ(clampOnly("#define AT(i) PAL[i]\nconst float PAL[4] = float[4](1.,2.,3.,4.);\n"
                        "#define ROW(m, i) M[i][m]\nmat3 M;\nfloat f(){ return AT(4) + ROW(1, 2); }"),
              "#define AT(i) PAL[int(clamp(float(i),0.0,3.0))]\nconst float PAL[4] = float[4](1.,2.,3.,4.);\n"
              "#define ROW(m, i) M[int(clamp(float(i),0.0,2.0))][int(clamp(float(m),0.0,2.0))]\nmat3 M;\n"
              "float f(){ return AT(4) + ROW(1, 2); }");
    // Names declared with different types, a parameter named like an array, and literal indices:
    // left alone.
    const std::string untyped = "void f(){ float a[4]; } void g(){ vec2 a; }\n#define A(i) a[i]\n#define P(PAL) PAL[0]\n"
                                "float PAL[3];\n#define Q(PAL, i) PAL[i]\n#define L PAL[1]";
    EXPECT_EQ(clampOnly(untyped), untyped);
    // Arrays of one type with different sizes: clamped with length().
    EXPECT_EQ(clampOnly("void f(){ float b[4]; } void g(){ float b[2]; }\n#define B(i) b[i]"),
              "void f(){ float b[4]; } void g(){ float b[2]; }\n#define B(i) b[int(clamp(float(i),0.0,float(b.length()-1)))]");
}
