// What the site refuses, toyhost refuses (issue 30): texture2D is GLSL ES 1.00's, WebGL2 has no such
// function (webref probe cp_texture2D), while Mesa 22 still compiles it in a 3.00 shader. A text
// that defines texture2D as a macro compiles, as on the site. (A function of that name: Mesa
// refuses to redefine a built-in, the site accepts it; not covered here.) Expressions and call
// chains deeper than Chrome's 256 are refused as Chrome refuses them (webref probes cp_expr_deep,
// cp_expr_long_sum, cp_call_deep), and a long sum of constants, which ANGLE folds, is not.
#include "GlTestSupport.h"

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

// Whether `image` compiles and renders one frame; `message` gets the error when it does not.
bool renders(const std::string& name, const std::string& image, std::string& message) {
    const std::filesystem::path dir = freshOutputDir("gl/site-strictness/" + name);
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", image);
    Result<Shadertoy> toy = Shadertoy::load(dir);
    if (!toy.ok()) return message = toy.error().text(), false;
    bool ok = false;
    runOnGlThread([&] {
        SessionSettings settings;
        settings.width = 4;
        settings.height = 4;
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*toy, settings);
        if (!made.ok()) return void(message = made.error().text());
        ok = (*made)->step().ok();
    });
    return ok;
}

TEST(SiteStrictness, Texture2DIsRefusedUnlessTheShaderDefinesIt) {
    const std::string call = "void mainImage(out vec4 o, in vec2 fc) { o = vec4(texture2D(iChannel0, fc).x, 0.5, 0.25, 1.0); }\n";
    std::string message;
    EXPECT_FALSE(renders("call", call, message));
    EXPECT_NE(message.find("texture2D"), std::string::npos) << message;
    EXPECT_TRUE(renders("macro", "#define texture2D texture\n" + call, message)) << message;
    EXPECT_TRUE(renders("comment", "// texture2D(iChannel0, p) was WebGL 1\n"
                                   "void mainImage(out vec4 o, in vec2 fc) { o = texture(iChannel0, fc); }\n",
                        message))
        << message;
}

TEST(SiteStrictness, ExpressionsAndCallsDeeperThanChromesLimitAreRefused) {
    std::string nested = "ONE";
    for (int i = 0; i < 300; ++i) nested = "(" + nested + " * 1.001)";
    std::string message;
    EXPECT_FALSE(renders("expr-deep",
                         "void mainImage(out vec4 o, in vec2 fc) { float ONE = iResolution.z;\n"
                         "  float v = " + nested + ";\n  o = vec4(v * 0.1, 0.5, 0.25, 1.0); }\n",
                         message));
    EXPECT_NE(message.find("image.glsl:2"), std::string::npos) << message;
    EXPECT_NE(message.find("the site refuses this"), std::string::npos) << message;

    std::string sum = "fc.x * 0.0";
    for (int i = 1; i < 400; ++i) sum += " + fc.x * 0.0001";
    EXPECT_FALSE(renders("long-sum", "void mainImage(out vec4 o, in vec2 fc) { o = vec4(" + sum + ", 0.5, 0.25, 1.0); }\n",
                         message));
    EXPECT_NE(message.find("the site refuses this"), std::string::npos) << message;

    std::string chain = "float c0(float x) { return x + 0.001; }\n";
    for (int i = 1; i < 300; ++i)
        chain += "float c" + std::to_string(i) + "(float x) { return c" + std::to_string(i - 1) + "(x) + 0.001; }\n";
    EXPECT_FALSE(renders("call-deep", chain + "void mainImage(out vec4 o, in vec2 fc) { o = vec4(c299(fc.x), 0.5, 0.25, 1.0); }\n",
                         message));
    EXPECT_NE(message.find("function calls nested 302 deep: the site refuses this"), std::string::npos) << message;

    // 400 constants summed: ANGLE folds them into one while parsing, and the site runs it.
    std::string constants = "0.0";
    for (int i = 1; i < 400; ++i) constants += " + 0.001";
    EXPECT_TRUE(renders("constant-sum", "void mainImage(out vec4 o, in vec2 fc) { o = vec4(" + constants + ", 0.5, 0.25, 1.0); }\n",
                        message))
        << message;
}

}  // namespace
}  // namespace toyhost::testing
