// IntegerConstantFold (through GlslRewrite): integer constant operations GLSL ES leaves undefined
// are written as the value ANGLE's folder gives them (division and remainder by 0, INT_MIN / -1,
// `%` of a negative, shifts by less than 0 or more than 31), on the same lines; everything else,
// and every operand that is not a constant, is left to the driver.
#include <gtest/gtest.h>

#include <string>

#include "shader/GlslRewrite.h"

using namespace toyhost;

namespace {

std::string foldOnly(const std::string& text) {
    GlslRewriteOptions options;
    options.zeroInit = options.rename = options.clampIndices = options.opaqueDivisors = false;
    return rewriteLikeWebGL(text, options);
}

}  // namespace

TEST(IntegerConstantFold, DivisionAndRemainderByZeroAreTheLargestValue) {
    EXPECT_EQ(foldOnly("int a = 7 / 0; int b = 7 % 0; uint c = 7u / 0u; uint d = 7u % 0u;"),
              "int a = 2147483647; int b = 2147483647; uint c = 4294967295u; uint d = 4294967295u;");
    EXPECT_EQ(foldOnly("int a = -7 / 0;"), "int a = 2147483647;");
}

TEST(IntegerConstantFold, MostNegativeByMinusOneIsIntMax) {
    EXPECT_EQ(foldOnly("const int Q = int(0x80000000u) / -1;"), "const int Q = 2147483647;");
    EXPECT_EQ(foldOnly("int q = (-2147483647 - 1) / (-1);"), "int q = 2147483647;");
    EXPECT_EQ(foldOnly("int q = 0x80000000 / -1;"), "int q = 2147483647;");
}

TEST(IntegerConstantFold, RemainderOfANegativeIsZero) {
    EXPECT_EQ(foldOnly("int r = -7 % 3; int s = 7 % -3; int t = int(0x80000000u) % -1;"),
              "int r = 0; int s = 0; int t = 0;");
}

TEST(IntegerConstantFold, ShiftsOutOfRangeAreZero) {
    EXPECT_EQ(foldOnly("int a = 1 << 32; int b = -8 >> 33; uint c = 1u << 32u; int d = 1 << -1;"
                       " uint e = 0x80000000u >> 32u; int f = 1 << 16 + 16;"),
              "int a = 0; int b = 0; uint c = 0u; int d = 0; uint e = 0u; int f = 0;");
}

TEST(IntegerConstantFold, DefinedOperationsAreLeftToTheDriver) {
    const std::string text = "int a = 7 / 2; int b = -7 / 2; int c = 7 % 3; int d = 1 << 31; int e = -8 >> 1;"
                             " uint f = 7u % 3u; int g = 7 / -1; int h = 2147483647 + 1;";
    EXPECT_EQ(foldOnly(text), text);
}

TEST(IntegerConstantFold, NonConstantOperandsAreLeftAlone) {
    // A browser does not fold these either: the value is the GPU's.
    const std::string text = "int f(int x, ivec2 v, int a[2]){ return x / 0 + (x * 7) / 0 + 7 / x + v.x % 0"
                             " + a[1] / 0 + g(1) / 0 + (x << 32) + x / 7 / 0 + int(2.5) / 0; }";
    EXPECT_EQ(foldOnly(text), text);
}

TEST(IntegerConstantFold, OnlyTheOperationIsReplacedInsideALargerExpression) {
    EXPECT_EQ(foldOnly("int a = x - -7 % 3 * y;"), "int a = x - 0 * y;");
    EXPECT_EQ(foldOnly("int a = x + 2 * 3 / 0;"), "int a = x + 2147483647;");
    EXPECT_EQ(foldOnly("bool b = 1 < 1 << 32;"), "bool b = 1 < 0;");
    EXPECT_EQ(foldOnly("int a = 1 + 2 << 40 | x;"), "int a = 0 | x;");
    EXPECT_EQ(foldOnly("return c ? 7 / 0 : 1;"), "return c ? 2147483647 : 1;");
    EXPECT_EQ(foldOnly("int a = 7 / 0 / x;"), "int a = 2147483647 / x;");
}

TEST(IntegerConstantFold, NestedOperationsTakeTheOutermostValue) {
    EXPECT_EQ(foldOnly("int a = (7 / 0) % -1;"), "int a = 0;");
    EXPECT_EQ(foldOnly("int a = 7 / (1 / 0);"), "int a = 7 / (2147483647);");
    EXPECT_EQ(foldOnly("int a = -(7 << 40);"), "int a = -(0);");
}

TEST(IntegerConstantFold, ConstantsDeclaredOnceAreRead) {
    EXPECT_EQ(foldOnly("const int Z = 0, M = -1; const highp uint U = 3u; int a = 7 / Z; int b = int(0x80000000u) / M;"
                       " uint c = U << 40;"),
              "const int Z = 0, M = -1; const highp uint U = 3u; int a = 2147483647; int b = 2147483647;"
              " uint c = 0u;");
    // Z is also a parameter somewhere: it may be shadowed, so it is not read.
    const std::string shadowed = "const int Z = 0; int f(int Z){ return 7 / Z; }";
    EXPECT_EQ(foldOnly(shadowed), shadowed);
}

TEST(IntegerConstantFold, CastsOfFoldedValuesFoldAgain) {
    EXPECT_EQ(foldOnly("int a = x-(1<<33);"), "int a = x-(0);");
    EXPECT_EQ(foldOnly("uint a = uint(int(0x80000000u) / 0) << 32u;"), "uint a = 0u;");
}

TEST(IntegerConstantFold, LinesAndDirectivesStay) {
    EXPECT_EQ(foldOnly("int a = 7 /\n 0;\n#if 1 / 1\n#endif\nint b = a;"), "int a = 2147483647\n;\n#if 1 / 1\n#endif\nint b = a;");
    const std::string directive = "#define Q (7 / 0)\n#if 1 << 40\n#endif\n";
    EXPECT_EQ(foldOnly(directive), directive);
}

TEST(IntegerConstantFold, CompoundAssignmentsAndMembersAreNotOperations) {
    const std::string text = "const int N = 7; void f(){ int x = 1; x <<= 40; x /= 0; x = s.N / 0; }";
    EXPECT_EQ(foldOnly(text), text);
}

TEST(IntegerConstantFold, AnyTextStaysBoundedInStackAndTime) {
    // 100000 nested parentheses around a division by zero, and 20000 divisions by a parenthesised
    // operand: read up to the guards, never a crash or quadratic time.
    const std::string open(100000, '('), close(100000, ')');
    const std::string deep = "int a = " + open + "7 / 0" + close + ";";
    EXPECT_EQ(foldOnly(deep).size(), deep.size() + std::string("2147483647").size() - std::string("7 / 0").size());
    std::string chain = "int a = x";
    for (int i = 0; i < 20000; ++i) chain = "(" + chain + ") / (1 + 2)";
    EXPECT_EQ(foldOnly(chain + ";"), chain + ";");
}

// Issue 42: a local declared after a comma, in a statement or a for-init, shadows the constant:
// the browser divides by the local (7 / ZC with ZC = 2: 3), so nothing is folded.
TEST(IntegerConstantFold, ALocalAfterACommaShadowsTheConstant) {
    const std::string code = "const int ZC = 0;\nconst int MN = 0;\nvoid f(){ int a = 2, ZC = 2; int q = 7 / ZC;"
                             " for (int b = 0, MN = 3; b < 1; b++) q = 7 % MN; }";
    EXPECT_EQ(foldOnly(code), code);
    // Commas of a call or a constructor declare nothing: the constant is still folded.
    EXPECT_EQ(foldOnly("const int Z = 0;\nvoid f(){ ivec3 v = ivec3(1, Z, 2); int q = 7 / Z; }"),
              "const int Z = 0;\nvoid f(){ ivec3 v = ivec3(1, Z, 2); int q = 2147483647; }");
}

// Issue 42: ANGLE folds constant vectors too, component by component (a scalar operand applies to
// every component), and the browser folds the expanded text, so a constant written as a macro is
// one as well.
TEST(IntegerConstantFold, ConstantVectorsAreFoldedComponentByComponent) {
    EXPECT_EQ(foldOnly("ivec2 a = ivec2(7)/0; ivec2 b = ivec2(7)%0; uvec2 c = uvec2(7u)/0u;"),
              "ivec2 a = ivec2(2147483647, 2147483647); ivec2 b = ivec2(2147483647, 2147483647); "
              "uvec2 c = uvec2(4294967295u, 4294967295u);");
    EXPECT_EQ(foldOnly("ivec2 r = ivec2(-7)%3; ivec2 s = ivec2(1)<<33; ivec2 t = ivec2(-8)>>40;"),
              "ivec2 r = ivec2(0, 0); ivec2 s = ivec2(0, 0); ivec2 t = ivec2(0, 0);");
    EXPECT_EQ(foldOnly("const ivec2 CV = ivec2(7,0);\nint q = CV.x/CV.y; ivec3 w = ivec3(CV, 1) / ivec3(2, 0, 1);"),
              "const ivec2 CV = ivec2(7,0);\nint q = 2147483647; ivec3 w = ivec3(3, 2147483647, 1);");
    // Defined operations and non-constant operands stay the driver's.
    const std::string same = "ivec2 a = ivec2(7)/2; uniform ivec2 u; ivec2 b = u/0; ivec2 c = ivec2(7)/ivec3(0);";
    EXPECT_EQ(foldOnly(same), same);
}

TEST(IntegerConstantFold, MacroOperandsAreConstants) {
    EXPECT_EQ(foldOnly("#define Z 0\nint a = 7/Z; int b = 7%Z;\nconst int QZ = 7/Z;\nuint c = 7u/uint(Z);"),
              "#define Z 0\nint a = 2147483647; int b = 2147483647;\nconst int QZ = 2147483647;\nuint c = 4294967295u;");
    // Only a body that is one operand: `7 / N` with `#define N 1 - 1` is (7 / 1) - 1 = 6 for the browser.
    const std::string expression = "#define N 1 - 1\n#define S S\nint a = 7 / N; int b = 7 / S;";
    EXPECT_EQ(foldOnly(expression), expression);
}
