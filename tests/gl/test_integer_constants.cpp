// No shader can crash toyhost through Mesa's constant folder, and every integer constant edge gives
// the browser's value (issue 30). INT_MIN / -1 in a constant expression ended the process with
// SIGFPE (Mesa 22.3 folds with the host's idiv; core/DivisionOverflowTrap.h completes it). GLSL ES
// leaves these operations undefined; ANGLE's folder, which every browser runs, gives INT_MAX for
// division and remainder by 0 and for INT_MIN / -1, UINT_MAX for uint by 0, 0 for `%` of a negative
// and for shifts out of [0, 31]; the source rewrite writes those values (shader/IntegerConstantFold.h).
// Checked in headless Chromium with ../shared/webref's int_divzero_const, cp_const_intmin_div,
// int_mod_neg (cell 0) and shift_const.
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
    int expectedTopByte;     // (k >> 24) & 255: GLSL's value, or ANGLE's where GLSL leaves it undefined
    int expectedLowByte;     // k & 255
};

TEST(IntegerConstants, EveryEdgeCompilesAndGivesTheBrowsersValue) {
    const std::vector<Edge> edges = {
        {"(-2147483647 - 1) / -1", 0x7F, 0xFF},
        {"int(0x80000000u) / -1", 0x7F, 0xFF},
        {"(-2147483647 - 1) % -1", 0, 0},
        {"int(0x80000000u) % -1", 0, 0},
        {"(-2147483647 - 1) / 1", 0x80, 0},
        {"7 / -1", 0xFF, 0xF9},
        {"-7 % 3", 0, 0},
        {"7 % 3", 0, 1},
        {"1 / 0", 0x7F, 0xFF},
        {"1 % 0", 0x7F, 0xFF},
        {"0 / 0", 0x7F, 0xFF},
        {"(-2147483647 - 1) / 0", 0x7F, 0xFF},
        {"int(7u / 0u)", 0xFF, 0xFF},
        {"1 << 32", 0, 0},
        {"1 << 33", 0, 0},
        {"1 << -1", 0, 0},
        {"-1 >> 40", 0, 0},
        {"int(0x80000000u >> 32u)", 0, 0},
        {"-8 >> 1", 0xFF, 0xFC},
        {"int(1u << 31) / -1", 0x7F, 0xFF},
        // A vector: not rewritten; Mesa's idiv traps and core/DivisionOverflowTrap completes it.
        {"(ivec2(int(0x80000000u)) / -1).x", 0x7F, 0xFF},
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

// The browsers' probe as it is written: a global constant whose value is only in a name.
TEST(IntegerConstants, AGlobalConstantOfIntMinByMinusOneIsIntMaxAsInTheBrowser) {
    const std::vector<std::uint8_t> pixels = renderImageOnce(
        freshOutputDir("gl/integer-constants-global"),
        "const int Z = 0;\nconst int Q = int(0x80000000u) / -1 + 7 / Z;\n"
        "void mainImage(out vec4 o, in vec2 f) {\n"
        "    o = vec4(float((Q >> 24) & 255) / 255.0, float(Q & 255) / 255.0, 0.25, 1.0);\n}\n");
    ASSERT_EQ(pixels.size(), 64u);
    // INT_MAX + INT_MAX wraps to -2: top byte 0xFF, low byte 0xFE.
    EXPECT_EQ(pixels[0], 0xFF);
    EXPECT_EQ(pixels[1], 0xFE);
}

}  // namespace
}  // namespace toyhost::testing
