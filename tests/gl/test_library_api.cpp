// The library API (include/toyhost/): a Shadertoy loaded from a folder or export text, a Session
// headless or on the caller's current context, stepped and read back into memory. Frames equal
// the CLI's; the caller's GL state is what it was; errors come back as data.
#include "GlTestSupport.h"

#include <GLES3/gl3.h>

#include <toyhost/Session.h>
#include <toyhost/Version.h>

#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

TEST(LibraryApi, TheVersionMacroAndFunctionAgree) {
    EXPECT_STREQ(versionString(), TOYHOST_VERSION_STRING);
    EXPECT_EQ(version().major * 10000 + version().minor * 100 + version().patch, TOYHOST_VERSION);
}

TEST(LibraryApi, AHeadlessFrameEqualsTheClisPng) {
    TOYHOST_REQUIRE_SHARED("shadertoys/MdXyzX/image.glsl");
    const fs::path dir = freshOutputDir("library-api/cli");
    auto cli = runToyhost("run " + (sourceDir() / "shadertoys/ocean").string() +
                          " --size 96x54 --frames 3 --fps 30 --date 2026-01-01T00:00:00 --quiet --out " +
                          (dir / "f_%d.png").string());
    ASSERT_EQ(cli.exitCode, 0) << cli.output;
    Result<Image8> expected = loadImageFile(dir / "f_2.png");  // rows bottom first (image/Image.h)
    ASSERT_TRUE(expected.ok()) << expected.error().text();

    Result<Shadertoy> ocean = Shadertoy::load(sourceDir() / "shadertoys/ocean");
    ASSERT_TRUE(ocean.ok()) << ocean.error().text();
    SessionSettings settings;
    settings.width = 96;
    settings.height = 54;
    settings.fps = 30;
    settings.date = "2026-01-01T00:00:00";
    // Created, used and destroyed on one thread with a large stack, as the header asks.
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*ocean, settings);
        ASSERT_TRUE(session.ok()) << session.error().text();
        for (int i = 0; i < 3; ++i) ASSERT_TRUE((*session)->step().ok());
        std::vector<std::uint8_t> pixels(96 * 54 * 4), topFirst(96 * 54 * 4);
        ASSERT_TRUE((*session)->read("Image", pixels, RowOrder::BottomFirst).ok());
        EXPECT_EQ(pixels, expected->rgba) << "the library's frame differs from the CLI's";
        ASSERT_TRUE((*session)->read("Image", topFirst, RowOrder::TopFirst).ok());
        EXPECT_TRUE(std::equal(topFirst.begin(), topFirst.begin() + 96 * 4, pixels.end() - 96 * 4))
            << "top first: the file's first row first";
        EXPECT_EQ((*session)->frame(), 3);
        std::vector<std::uint8_t> wrongSize(10);
        EXPECT_FALSE((*session)->read("Image", wrongSize).ok());
        EXPECT_FALSE((*session)->read("Buffer A", pixels).ok()) << "the ocean has no Buffer A";
    });
}

class LibraryOnCurrentContext : public GlTest {};

// The caller's context: toyhost renders into its own targets and leaves the caller's state as it
// was (framebuffer, program, viewport, active texture, a bound texture).
TEST_F(LibraryOnCurrentContext, RendersAndKeepsTheCallersGlState) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/pingpong-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    ASSERT_TRUE(context_->makeCurrent().ok());
    GLuint framebuffer = 0, texture = 0;
    glGenTextures(1, &texture);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    glViewport(1, 2, 3, 4);
    const GLuint program = glCreateProgram();  // never linked: only its name is bound below
    auto state = [] {
        GLint values[6] = {};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &values[0]);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &values[1]);
        glGetIntegerv(GL_TEXTURE_BINDING_2D, &values[2]);
        GLint viewport[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        values[3] = viewport[0] * 1000 + viewport[1] * 100 + viewport[2] * 10 + viewport[3];
        glGetIntegerv(GL_CURRENT_PROGRAM, &values[4]);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &values[5]);
        return std::vector<GLint>(values, values + 6);
    };
    const std::vector<GLint> before = state();

    SessionSettings settings;
    settings.width = 16;
    settings.height = 8;
    settings.floatImage = true;
    Result<std::unique_ptr<Session>> session = Session::createOnCurrentContext(*probe, settings);
    ASSERT_TRUE(session.ok()) << session.error().text();
    EXPECT_EQ(state(), before) << "creating the session changed the caller's state";
    for (int i = 0; i < 3; ++i) ASSERT_TRUE((*session)->step().ok());
    EXPECT_EQ(state(), before) << "rendering changed the caller's state";
    std::vector<float> a(16 * 8 * 4);
    ASSERT_TRUE((*session)->read("Buffer A", a, RowOrder::BottomFirst).ok());
    EXPECT_EQ(state(), before) << "reading changed the caller's state";
    EXPECT_NE((*session)->imageTexture(), 0u);
    ASSERT_TRUE((*session)->drawImage(framebuffer, 0, 0, 4, 4).ok());
    EXPECT_EQ(state(), before) << "drawing into the caller's framebuffer changed its state";
    session = Error("done", Code::Internal);
    EXPECT_EQ(state(), before) << "destroying the session changed the caller's state";
    glDeleteProgram(program);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
}

TEST(LibraryApi, ErrorsAreDataNamingThePassAndLine) {
    const fs::path dir = freshOutputDir("library-api/broken");
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", "void mainImage(out vec4 c, in vec2 f) {\n    c = vec4(undefined_thing);\n}\n");
    Result<Shadertoy> broken = Shadertoy::load(dir);
    ASSERT_TRUE(broken.ok()) << "loading checks no GLSL: " << broken.error().text();
    Result<std::unique_ptr<Session>> session = Error("not created", Code::Internal);
    runOnGlThread([&] { session = Session::createHeadless(*broken); });
    ASSERT_FALSE(session.ok());
    const Diagnostic& first = session.error().first();
    EXPECT_EQ(first.code, Code::ShaderCompile);
    EXPECT_EQ(first.pass, "Image");
    EXPECT_EQ(first.line, 2);
    EXPECT_EQ(first.file, (dir / "image.glsl").string());

    Result<Shadertoy> notJson = Shadertoy::fromExportJson("{\"Shader\": ", "given.json");
    ASSERT_FALSE(notJson.ok());
    EXPECT_NE(notJson.error().text().find("given.json"), std::string::npos) << notJson.error().text();
}

}  // namespace
}  // namespace toyhost::testing
