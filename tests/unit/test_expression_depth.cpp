// ExpressionDepth: the estimate behind "the site refuses this" for expressions nested deeper than
// Chrome's 256 (webref probes cp_expr_deep: 300 nested parentheses, cp_expr_long_sum: 400 terms),
// and ordinary code far below it. Pure.
#include <gtest/gtest.h>

#include <string>

#include "shader/ExpressionDepth.h"

using namespace toyhost;

namespace {

std::string nested(int depth) {
    std::string v = "ONE";
    for (int i = 0; i < depth; ++i) v = "(" + v + " + 0.001)";
    return "void f(float ONE) {\n  float a = 1.0;\n  float v = " + v + ";\n}\n";
}

std::string longSum(int terms) {
    std::string v = "x * 0.0";
    for (int i = 1; i < terms; ++i) v += " + x * 0.001";
    return "float g(float x) { return " + v + "; }\n";
}

}  // namespace

TEST(ExpressionDepth, NestedParenthesesCountOnePerLevel) {
    const DeepestStatement deep = deepestStatement(nested(300));
    EXPECT_GT(deep.depth, kSiteExpressionDepthLimit);
    EXPECT_LT(deep.depth, 310);
    EXPECT_EQ(deep.line, 3);
    EXPECT_LT(deepestStatement(nested(200)).depth, kSiteExpressionDepthLimit);
}

TEST(ExpressionDepth, ALongSumIsAsDeepAsItsTerms) {
    EXPECT_GT(deepestStatement(longSum(400)).depth, kSiteExpressionDepthLimit);
    EXPECT_LT(deepestStatement(longSum(400)).depth, 410);
    EXPECT_LT(deepestStatement(longSum(100)).depth, kSiteExpressionDepthLimit);
}

TEST(ExpressionDepth, ArgumentsAreSiblingsNotLevels) {
    // 300 arguments of one call: each is shallow, the call is too.
    std::string args = "1.0";
    for (int i = 0; i < 300; ++i) args += ", 1.0 + 2.0";
    EXPECT_LT(deepestStatement("float[301] a = float[301](" + args + ");").depth, 10);
    EXPECT_LT(deepestStatement("void m(out vec4 o, in vec2 fc) { o = vec4(fc.x * 2.0 + sin(fc.y), 0.5, 0.25, 1.0); }").depth, 10);
}

namespace {
// The webref probe cp_call_deep's shape: c0 .. c{n-1}, each calling the one before, mainImage
// calling the last.
std::string callChain(int functions) {
    std::string code = "float c0(float x) { return x + 0.001; }\n";
    for (int i = 1; i < functions; ++i)
        code += "float c" + std::to_string(i) + "(float x) { return c" + std::to_string(i - 1) + "(x) + 0.001; }\n";
    code += "void mainImage(out vec4 o, in vec2 fc) { o = vec4(c" + std::to_string(functions - 1) +
            "(fc.x), 0.5, 0.25, 1.0); }\n";
    return code;
}
}  // namespace

TEST(CallDepth, AChainCountsEveryFunctionFromTheSitesMain) {
    // main -> mainImage -> c299 -> ... -> c0: 302, over Chrome's 256 (the browser refuses cp_call_deep).
    const DeepestCallChain deep = deepestCallChain(callChain(300));
    EXPECT_EQ(deep.depth, 302);
    EXPECT_EQ(deep.line, 301) << "mainImage's line";
    EXPECT_LE(deepestCallChain(callChain(200)).depth, kSiteCallDepthLimit);
}

TEST(CallDepth, BuiltinsOverloadsRecursionAndNoEntryPoint) {
    // Built-ins and constructors are not functions of the shader; many calls side by side stay shallow.
    EXPECT_EQ(deepestCallChain("float f(float x) { return sin(x) + cos(x); }\n"
                               "float g(float x) { return f(x) + f(x * 2.0) + vec2(x).x; }\n"
                               "void mainImage(out vec4 o, in vec2 p) { o = vec4(g(p.x) + f(p.y)); }\n")
                  .depth,
              4);
    // Overloads share a name; a cycle (refused by GLSL anyway) ends the chain instead of looping.
    EXPECT_EQ(deepestCallChain("float f(float x) { return f(x, 1.0); }\nfloat f(float x, float y) { return x; }\n"
                               "void mainImage(out vec4 o, in vec2 p) { o = vec4(f(p.x)); }\n")
                  .depth,
              3);
    EXPECT_EQ(deepestCallChain("float f(float x) { return x; }\n").depth, 0) << "no entry point";
    EXPECT_EQ(deepestCallChain("void mainSound() {}\n").depth, 2) << "main() -> mainSound()";
}

TEST(ExpressionDepthAtLeast, OperationsCountAndConstantsFold) {
    EXPECT_GT(deepestStatementAtLeast(nested(300)).depth, kSiteExpressionDepthLimit);
    EXPECT_EQ(deepestStatementAtLeast(nested(300)).line, 3);
    EXPECT_LE(deepestStatementAtLeast(nested(200)).depth, kSiteExpressionDepthLimit);
    EXPECT_GT(deepestStatementAtLeast(longSum(400)).depth, kSiteExpressionDepthLimit);
    // In a body, 2 levels above the statement. x + 1 + 2: ((x + 1) + 2), two operations over a leaf.
    EXPECT_EQ(deepestStatementAtLeast("float f(float x) { return x + 1.0 + 2.0; }").depth, 2 + 3);
    // Constants alone fold into one, however many: 1.0 + 2.0 + ... is one constant.
    std::string constants = "1.0";
    for (int i = 0; i < 400; ++i) constants += " + 2.0";
    EXPECT_EQ(deepestStatementAtLeast("float f() { return " + constants + "; }").depth, 2 + 1);
    EXPECT_EQ(deepestStatementAtLeast("const float K = 2.0;\n#define M 3.0\nfloat f() { return K * M + vec2(1.0, K).y; }").depth, 2 + 1);
    // Parentheses are no level; calls, indices and members are.
    EXPECT_EQ(deepestStatementAtLeast("float f(float x) { return ((((x)))); }").depth, 2 + 1);
    EXPECT_EQ(deepestStatementAtLeast("float f(vec3 a) { return g(a.xy[0]); }").depth, 2 + 4);
    // A constant condition keeps one branch (ANGLE folds the selection): the shallower counts.
    EXPECT_EQ(deepestStatementAtLeast("float f(float x) { return true ? x : x + x + x; }").depth, 2 + 1);
    // A declaration adds itself and its initialisation; an assignment is an operation; a global's
    // initialiser sits under its declaration.
    EXPECT_EQ(deepestStatementAtLeast("void f(float x) { highp float v = x * x; }").depth, 4 + 2);
    EXPECT_EQ(deepestStatementAtLeast("void f(float x) { float v; v = x * x; }").depth, 2 + 3);
    EXPECT_EQ(deepestStatementAtLeast("uniform float u; float g = u * u;").depth, 2 + 2);
}

namespace {
// `float v = ` (or `v = `) n nested products of a variable, as the browser was checked with.
std::string products(int n, bool declaration) {
    std::string v = "ONE";
    for (int i = 0; i < n; ++i) v = "(" + v + " * 1.001)";
    return "void mainImage(out vec4 o, in vec2 fc) { float ONE = iResolution.z; float v;\n  " +
           std::string(declaration ? "float w = " : "v = ") + v + ";\n  o = vec4(v); }\n";
}
}  // namespace

TEST(ExpressionDepthAtLeast, ChromesBoundaryExactly) {
    // Headless Chromium 156 (../shared/webref): a declaration of 251 products compiles, 252 does
    // not; an assignment of 252 compiles, 253 does not.
    EXPECT_LE(deepestStatementAtLeast(products(251, true)).depth, kSiteExpressionDepthLimit);
    EXPECT_GT(deepestStatementAtLeast(products(252, true)).depth, kSiteExpressionDepthLimit);
    EXPECT_LE(deepestStatementAtLeast(products(252, false)).depth, kSiteExpressionDepthLimit);
    EXPECT_GT(deepestStatementAtLeast(products(253, false)).depth, kSiteExpressionDepthLimit);
}

TEST(ExpressionDepthAtLeast, NeverAboveTheEstimateOnOrdinaryCode) {
    const std::string code = "float h(vec2 p) { return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453); }\n"
                             "void mainImage(out vec4 o, in vec2 fc) {\n"
                             "  vec2 uv = (2.0 * fc - iResolution.xy) / iResolution.y; float d = length(uv) - 0.5;\n"
                             "  for (int i = 0; i < 4; i++) { d = min(d, abs(uv.x - float(i) * 0.1) - 0.01); }\n"
                             "  o = vec4(vec3(smoothstep(0.0, 0.01, d)) * h(fc), 1.0); }\n";
    const DeepestStatement atLeast = deepestStatementAtLeast(code);
    EXPECT_GT(atLeast.depth, 5);
    EXPECT_LE(atLeast.depth, deepestStatement(code).depth + 6);
    EXPECT_LT(atLeast.depth, 24);
}

TEST(ExpressionDepthAtLeast, AnyTextKeepsTheStackSmall) {
    // 100000 nested parentheses and as many minus signs: the statement is unread past the guard (no
    // crash, no quadratic time); only the declaration's words count, as leaves.
    const std::string open(100000, '('), close(100000, ')'), minus(100000, '-');
    EXPECT_LE(deepestStatementAtLeast("float f(float x) { return " + open + "x" + close + "; }").depth, 1);
    EXPECT_LE(deepestStatementAtLeast("float f(float x) { return " + minus + "x; }").depth, 1);
}

TEST(CallDepth, ChromesBoundaryExactly) {
    // Headless Chromium 156 (../shared/webref): 254 chained functions under mainImage compile, 255
    // do not ("main -> mainImage -> c253 .. c0" is 256 deep).
    EXPECT_EQ(deepestCallChain(callChain(254)).depth, kSiteCallDepthLimit);
    EXPECT_GT(deepestCallChain(callChain(255)).depth, kSiteCallDepthLimit);
}

TEST(CallDepth, AChainIsExactUnlessItPassesThroughAnOverload) {
    EXPECT_TRUE(deepestCallChain(callChain(300)).exact);
    EXPECT_FALSE(deepestCallChain("float f(float x) { return x; }\nfloat f(vec2 x) { return g(x.x); }\n"
                                  "float g(float x) { return x; }\n"
                                  "void mainImage(out vec4 o, in vec2 p) { o = vec4(f(p.x)); }\n")
                     .exact);
}
