// LoopCap: the iterations of `for` loops with constant bounds, nested loops multiplied, to warn
// where llvmpipe's 65535-iteration limit ends them early (the browser runs them all).
#include <gtest/gtest.h>

#include <string>

#include "shader/LoopCap.h"

using namespace toyhost;

namespace {

std::vector<std::int64_t> totals(const std::string& code) {
    std::vector<std::int64_t> out;
    for (const CountedLoop& loop : countedLoops(code)) out.push_back(loop.total);
    return out;
}

}  // namespace

TEST(LoopCap, LiteralAndConstantBounds) {
    EXPECT_EQ(totals("void f() { for (int i = 0; i < 100000; i++) {} }"), std::vector<std::int64_t>{100000});
    EXPECT_EQ(totals("void f() { for (int i = 10; i <= 20; i += 5) {} for (int j = 9; j >= 0; --j) {} }"),
              (std::vector<std::int64_t>{3, 10}));
    EXPECT_EQ(totals("const int N = 300 * 2;\n#define STEPS 1000\nvoid f() { for (int i = 0; i < N; ++i) {}\n"
                     "for (float t = 0.0; t < float(STEPS) / 2.0; t += 0.5) {} for (int k = -(N); k != N; k += 2) {} }"),
              (std::vector<std::int64_t>{600, 1000, 600}));
    EXPECT_EQ(totals("void f() { for (int i = 0; 100 > i; i++) {} }"), std::vector<std::int64_t>{100});
}

TEST(LoopCap, NestedLoopsCountEveryIterationOfEachLevel) {
    const std::vector<CountedLoop> loops =
        countedLoops("void f() {\n  for (int i = 0; i < 300; i++)\n    for (int j = 0; j < 300; j++) { x++; }\n"
                     "  for (int k = 0; k < 10; k++) { for (int m = 0; m < 20; m++) {} }\n}\n");
    ASSERT_EQ(loops.size(), 4u);
    EXPECT_EQ(loops[0].total, 300);
    EXPECT_EQ(loops[1].iterations, 300);
    EXPECT_EQ(loops[1].total, 300 + 300 * 300);
    EXPECT_EQ(loops[1].line, 3);
    EXPECT_EQ(loops[2].total, 10);  // a sibling, not nested in the 300 x 300
    EXPECT_EQ(loops[3].total, 10 + 200);
}

TEST(LoopCap, UnknownBoundsAreNotCounted) {
    EXPECT_TRUE(totals("void f(int n) { for (int i = 0; i < n; i++) {} for (int i = 0; i < 9; i *= 2) {} }").empty());
    EXPECT_TRUE(totals("const int N = 1;\nconst int N = 2;\nvoid f() { for (int i = 0; i < N; i++) {} }").empty());
    // An unknown outer loop: the inner one counts alone (a lower bound).
    EXPECT_EQ(totals("void f(int n) { for (int i = 0; i < n; i++) for (int j = 0; j < 70000; j++) {} }"),
              std::vector<std::int64_t>{70000});
}
