// No shader can crash toyhost through Mesa's constant folder: every integer constant edge compiles
// and renders (issue 30). INT_MIN / -1 and INT_MIN % -1 in a constant expression ended the process
// with SIGFPE (Mesa 22.3 folds with the host's idiv); browsers compile them and ANGLE folds them to
// INT_MAX (the quotient saturates) and 0, which toyhost now gives too (core/DivisionOverflowTrap.h;
// checked in headless Chromium with ../shared/webref's int_divzero_const and cp_const_intmin_div).
// Division and remainder by 0 and shifts by 32 or more are undefined in GLSL ES: they must compile
// and render, whatever value they give.
#include "GlTestSupport.h"

#include <toyhost/Session.h>

#include <vector>

namespace toyhost::testing {
namespace {

// An Image showing constant K's top byte in red and low byte in green (blue 0.25: it rendered).
std::string imageShowing(const char* expression) {
    return std::string("const int K = ") + expression +
           ";\nvoid mainImage(out vec4 o, in vec2 f) {\n"
           "    o = vec4(float((K >> 24) & 255) / 255.0, float(K & 255) / 255.0, 0.25, 1.0);\n}\n";
}

struct Edge {
    const char* expression;  // a constant int expression
    int expectedTopByte;     // (k >> 24) & 255 when GLSL defines it (or ANGLE does), else -1
    int expectedLowByte;     // k & 255, likewise
};

TEST(IntegerConstants, EveryEdgeCompilesAndRendersWithoutCrashing) {
    const std::vector<Edge> edges = {
        // The browser's INT_MAX: a known defect (below), checked by the expected failure.
        {"(-2147483647 - 1) / -1", -1, -1},
        {"int(0x80000000u) / -1", -1, -1},
        {"(-2147483647 - 1) % -1", 0, 0},
        {"int(0x80000000u) % -1", 0, 0},
        {"(-2147483647 - 1) / 1", 0x80, 0},
        {"7 / -1", 0xFF, 0xF9},
        {"1 / 0", -1, -1},
        {"1 % 0", -1, -1},
        {"0 / 0", -1, -1},
        {"(-2147483647 - 1) / 0", -1, -1},
        {"1 << 32", -1, -1},
        {"1 << 33", -1, -1},
        {"-1 >> 40", -1, -1},
        {"int(1u << 31) / -1", -1, -1},
    };
    const std::filesystem::path root = freshOutputDir("gl/integer-constants");
    int index = 0;
    for (const Edge& edge : edges) {
        SCOPED_TRACE(edge.expression);
        const std::filesystem::path dir = root / std::to_string(index++);
        const std::vector<std::uint8_t> pixels = renderImageOnce(dir, imageShowing(edge.expression));
        ASSERT_EQ(pixels.size(), 64u);
        EXPECT_EQ(pixels[2], 64);
        if (edge.expectedTopByte >= 0) EXPECT_EQ(pixels[0], edge.expectedTopByte);
        if (edge.expectedLowByte >= 0) EXPECT_EQ(pixels[1], edge.expectedLowByte);
    }
}

// Known defect, an expected failure (tests/CMakeLists.txt: known_defect.int_min_by_minus_one runs
// it with WILL_FAIL; disabled in the normal list): the browsers fold INT_MIN / -1 in a constant
// expression to INT_MAX (headless Chromium, webref probes cp_const_intmin_div and
// int_divzero_const), Mesa 22.3 folds it to INT_MIN without an idiv the trap could complete.
// This test asserts the browser's value, so it fails today and passes once that is fixed.
TEST(IntegerConstants, DISABLED_KnownDefectIntMinByMinusOneIsIntMaxAsInTheBrowser) {
    const std::vector<std::uint8_t> pixels =
        renderImageOnce(freshOutputDir("gl/integer-constants-known-defect"), imageShowing("int(0x80000000u) / -1"));
    ASSERT_EQ(pixels.size(), 64u);
    EXPECT_EQ(pixels[0], 0x7F) << "INT_MAX's top byte, as the browser folds it";
    EXPECT_EQ(pixels[1], 0xFF);
}

}  // namespace
}  // namespace toyhost::testing
