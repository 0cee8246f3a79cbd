// What the site refuses, toyhost refuses (issue 30): texture2D is GLSL ES 1.00's, WebGL2 has no such
// function (webref probe cp_texture2D), while Mesa 22 still compiles it in a 3.00 shader. A text
// that defines texture2D as a macro compiles, as on the site. (A function of that name: Mesa
// refuses to redefine a built-in, the site accepts it; not covered here.)
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

}  // namespace
}  // namespace toyhost::testing
