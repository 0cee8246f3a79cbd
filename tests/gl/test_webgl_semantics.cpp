// Rules where WebGL (ANGLE) and Mesa differ, each checked by a one-pass export against the value a
// browser shows (decided with ../shared/webref, its probes of the same names): locals and `out`
// parameters zero at every call, words Mesa reserves usable as names, `#ifdef lowp` false, asin and
// acos as precise as the browsers'.
#include "GlTestSupport.h"

#include <nlohmann/json.hpp>

#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// The red value (0-255) of pixel (2, 2) of the first frame of a one-pass export of `code` at 160x90.
int redOf(const std::string& name, const std::string& code) {
    const fs::path dir = freshOutputDir("webgl_semantics_" + name);
    nlohmann::json pass = {{"name", "Image"}, {"type", "image"}, {"inputs", nlohmann::json::array()},
                           {"outputs", {{{"id", 37}, {"channel", 0}}}}, {"code", code}};
    nlohmann::json exported = {{"Shader", {{"info", {{"id", name}, {"name", name}}}, {"renderpass", {pass}}}}};
    writeFile(dir / (name + ".json"), exported.dump());
    const CommandResult run = runToyhost("run '" + (dir / (name + ".json")).string() + "' --size 160x90 --frames 1 --quiet --out '" +
                                         (dir / "f.png").string() + "'");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    if (run.exitCode != 0) return -1;
    auto image = loadImageFile(dir / "f.png");
    EXPECT_TRUE(image.ok());
    if (!image.ok()) return -1;
    return image->rgba[(2 * image->width + 2) * 4];
}

// Browser: 4 calls, each from zero: 4 * 0.125 / 4 -> 32. Mesa alone: 80.
TEST(WebglSemantics, LocalsAreZeroAtEveryCall) {
    EXPECT_EQ(redOf("zi_callloop",
                    "float acc(float x) { float t; t += x; return t; }\n"
                    "void mainImage(out vec4 o, in vec2 fc) { float s = 0.0; for (int i = 0; i < int(iResolution.x) / 40; i++)"
                    " s += acc(0.125); o = vec4(s / 4.0, 0.0, 0.0, 1.0); }"),
              32);
}

// Browser: only the first call writes x: 1 / 4 -> 64.
TEST(WebglSemantics, OutParametersAreZeroAtEveryCall) {
    EXPECT_EQ(redOf("zi_outparam",
                    "void g(out float x, float y) { if (y < 0.0) x = 1.0; }\n"
                    "void mainImage(out vec4 o, in vec2 fc) { float s = 0.0; for (int i = 0; i < 4; i++) { float x;"
                    " g(x, (i == 0) ? -1.0 : 1.0); s += x; } o = vec4(s / 4.0, 0.0, 0.0, 1.0); }"),
              64);
}

// Browser: the member written only in the first call is zero in the other two: 0.5 / 3 -> 42.
TEST(WebglSemantics, OutStructMembersAreZeroAtEveryCall) {
    EXPECT_EQ(redOf("zi_outstruct",
                    "struct L { vec3 e; float k; };\n"
                    "void scene(vec2 p, out L l) { if (p.x < 0.0) l.e = vec3(1.0); l.k = 0.5; }\n"
                    "void mainImage(out vec4 o, in vec2 fc) { vec3 c = vec3(0.0); for (int i = 0; i < 3; i++) { L l;"
                    " scene(vec2(float(i) - 0.5, 0.0), l); c += l.e * l.k; } o = vec4(c / 3.0, 1.0); }"),
              42);
}

// Browser: each call's array starts at zero: 0.25 -> 64.
TEST(WebglSemantics, LocalArraysAreZeroAtEveryCall) {
    EXPECT_EQ(redOf("zi_array",
                    "float f() { float a[2]; a[1] += 0.125; return a[1]; }\n"
                    "void mainImage(out vec4 o, in vec2 fc) { float s = 0.0; for (int i = 0; i < 2; i++) s += f();"
                    " o = vec4(s, 0.0, 0.0, 1.0); }"),
              64);
}

// Browser: globals without an initialiser are zero (llvmpipe leaves vectors, arrays and structs
// undefined even with glsl_zero_init): 0.25 -> 64.
TEST(WebglSemantics, GlobalsWithoutInitialiserAreZero) {
    EXPECT_EQ(redOf("zi_globals", "struct L { vec3 e; float k; };\nfloat g; vec3 v; L l; float a[3];\n"
                                  "void mainImage(out vec4 o, in vec2 fc) { o = vec4(g + v.x + l.k + l.e.y + a[1] + 0.25, 0.0, 0.0, 1.0); }"),
              64);
}

// Words Mesa reserves and browsers accept (found by compiling every reserved word on both sides).
TEST(WebglSemantics, PackedAndDmatAreIdentifiers) {
    EXPECT_EQ(redOf("kw_packed", "void mainImage(out vec4 o, in vec2 fc) { float packed = 0.25; o = vec4(packed, 0.0, 0.0, 1.0); }"),
              64);
    EXPECT_EQ(redOf("kw_dmat", "#define M dmat3\nfloat dmat2x4(float x) { return x; }\n"
                               "void mainImage(out vec4 o, in vec2 fc) { float M = 0.25; o = vec4(dmat2x4(dmat3), 0.0, 0.0, 1.0); }"),
              64);
}

// Browser: lowp is a keyword, not a macro, so the #error is skipped; white.
TEST(WebglSemantics, IfdefLowpIsFalse) {
    EXPECT_EQ(redOf("lowp_ifdef", "#ifdef lowp\n#error lowp is a macro here\n#endif\n"
                                  "void mainImage(out vec4 o, in vec2 f) { o = vec4(1.0); }"),
              255);
}

// Desktop GPUs compute lowp in 32 bits (Mesa alone: 16, where 1 + 1e-4 is 1): 0.25 -> 64.
TEST(WebglSemantics, LowpAndMediumpStillComputeIn32Bits) {
    EXPECT_EQ(redOf("lowp_32bit", "void mainImage(out vec4 o, in vec2 f) { lowp float x = 1.0 + iTime * 0.0 + 1e-4;"
                                  " mediump float y = x - 1.0; o = vec4(y * 2500.0, 0.0, 0.0, 1.0); }"),
              64);
}

// Browsers give asin and acos to a few float steps (ANGLE on SwiftShader in headless Chromium:
// asin(0.9) = 1.11976945, acos(0.3) = 1.26610374; probe asin_acos); Mesa's polynomial was off by
// up to 4e-4 (1.12012327, 1.26594770). Red is 255 when every value (scalars and each vector
// component, at run time) is within 1e-5 of the true one, 0 otherwise; green counts the misses.
TEST(WebglSemantics, AsinAndAcosAreAsPreciseAsInTheBrowser) {
    EXPECT_EQ(redOf("asin_acos",
                    "void mainImage(out vec4 o, in vec2 fc) { float one = iResolution.x / 160.0;\n"
                    "  vec4 x = vec4(0.9, 0.5, -0.7, 0.999) * one;\n"
                    "  vec4 s = vec4(1.11976951, 0.52359878, -0.77539750, 1.52607124);\n"
                    "  vec4 c = vec4(0.45102681, 1.04719755, 2.34619382, 0.04472508);\n"
                    "  float miss = 0.0;\n"
                    "  miss += float(abs(asin(x.x) - s.x) > 1e-5) + float(abs(acos(x.x) - c.x) > 1e-5);\n"
                    "  miss += float(any(greaterThan(abs(asin(x.yz) - s.yz), vec2(1e-5))));\n"
                    "  miss += float(any(greaterThan(abs(acos(x.yzw) - c.yzw), vec3(1e-5))));\n"
                    "  miss += float(any(greaterThan(abs(asin(x) - s), vec4(1e-5))));\n"
                    "  miss += float(abs(acos(1.0 * one)) > 0.0) + float(abs(asin(1.0 * one) - 1.57079633) > 1e-6);\n"
                    "  o = vec4(miss == 0.0 ? 1.0 : 0.0, miss / 8.0, 0.0, 1.0); }"),
              255);
}

}  // namespace
}  // namespace toyhost::testing
