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
