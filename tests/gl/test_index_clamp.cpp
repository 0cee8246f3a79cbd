// Out-of-range dynamic indices give what the browser gives (issue 30, webref probe arr_oob): WebGL's
// translator clamps every dynamic index into the array, vector or matrix, so a loop `i <= 4` over
// a float[4] sums 1+2+3+4+4 = 14 (Mesa alone reads garbage or drops the code: 0 was seen).
#include "GlTestSupport.h"

#include <toyhost/Session.h>

#include <vector>

namespace toyhost::testing {
namespace {

TEST(IndexClampGl, OutOfRangeReadsAndWritesHitTheLastOrFirstElement) {
    const std::filesystem::path dir = freshOutputDir("gl/index-clamp");
    const std::vector<std::uint8_t> pixels = renderImageOnce(dir,
              "float loopSum(int n) { float a[4] = float[4](1.0, 2.0, 3.0, 4.0); float s = 0.0;\n"
              "  for (int i = 0; i <= n; i++) s += a[i]; return s; }\n"
              "float rdVec(int i, float one) { vec4 v = vec4(1.0, 2.0, 3.0, 4.0) * one; return v[i]; }\n"
              "float rdMat(int i, float one) { mat3 m = mat3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0) * one; return m[i].x; }\n"
              "float wrLocal(int i) { float a[4] = float[4](1.0, 2.0, 3.0, 4.0); a[i] = 9.0; return a[0] + a[1] + a[2] + a[3]; }\n"
              "void mainImage(out vec4 o, in vec2 f) {\n"
              "  float one = iResolution.z; int i1 = int(one);\n"
              "  o = vec4(loopSum(4 * i1) / 16.0, rdVec(7 * i1, one) / 16.0, rdMat(-5 * i1, one) / 16.0, 1.0);\n"
              "  if (f.x > 2.0) o.b = wrLocal(-1 * i1) / 32.0;\n}\n");
    ASSERT_EQ(pixels.size(), 64u);
    EXPECT_EQ(pixels[0], 223);  // 14 / 16
    EXPECT_EQ(pixels[1], 64);   // v[3] = 4
    EXPECT_EQ(pixels[2], 16);   // m[0].x = 1
    EXPECT_EQ(pixels[3 * 4 + 2], 143);  // a[0] = 9: 9 + 2 + 3 + 4 = 18, / 32
}

}  // namespace
}  // namespace toyhost::testing
