// The library API (include/toyhost/): a Shadertoy loaded from a folder or export text, a Session
// headless or on the caller's current context, stepped and read back into memory. Frames equal
// the CLI's; the caller's GL state is what it was; errors come back as data.
#include "EglDevicePlatform.h"
#include "GlTestSupport.h"

#include <GLES3/gl3.h>

#include <limits>
#include <optional>
#include <thread>

#include <toyhost/Compare.h>
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

// render()'s frames: the values read() gives for the same frame and type (8-bit and float, of an
// 8-bit Image and a float buffer), in either row order.
TEST(LibraryApi, RenderedFramesEqualSynchronousReads) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/pingpong-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    SessionSettings settings;
    settings.width = 16;
    settings.height = 8;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> reference = Session::createHeadless(*probe, settings);
        Result<std::unique_ptr<Session>> rendering = Session::createHeadless(*probe, settings);
        ASSERT_TRUE(reference.ok() && rendering.ok());
        const std::size_t values = 16 * 8 * 4;
        struct Expected {
            std::vector<std::uint8_t> bytes = std::vector<std::uint8_t>(16 * 8 * 4);
            std::vector<std::uint8_t> topFirst = std::vector<std::uint8_t>(16 * 8 * 4);
            std::vector<float> floats = std::vector<float>(16 * 8 * 4);
        };
        // Frames 0-3 of Image, then frames 4-7 of Buffer A, as read() gives them.
        auto passOf = [](int frame) { return frame < 4 ? "Image" : "Buffer A"; };
        std::vector<Expected> expected(8);
        for (int frame = 0; frame < 8; ++frame) {
            ASSERT_TRUE((*reference)->step().ok());
            Expected& e = expected[static_cast<std::size_t>(frame)];
            ASSERT_TRUE((*reference)->read(passOf(frame), e.bytes, RowOrder::BottomFirst).ok());
            ASSERT_TRUE((*reference)->read(passOf(frame), e.topFirst, RowOrder::TopFirst).ok());
            ASSERT_TRUE((*reference)->read(passOf(frame), e.floats, RowOrder::BottomFirst).ok());
        }
        std::vector<int> handed;
        for (const char* pass : {"Image", "Buffer A"}) {
            Session::RenderRequest request;
            request.frames = 4;
            request.pass = pass;
            Status done = (*rendering)->render(request, [&](const Session::RenderedFrame& frame) {
                handed.push_back(frame.frame);
                const Expected& e = expected[static_cast<std::size_t>(frame.frame)];
                std::vector<std::uint8_t> bytes(values), topFirst(values);
                std::vector<float> floats(values);
                EXPECT_TRUE(frame.read(std::span<std::uint8_t>(bytes), RowOrder::BottomFirst).ok());
                EXPECT_TRUE(frame.read(std::span<std::uint8_t>(topFirst)).ok());
                EXPECT_TRUE(frame.read(std::span<float>(floats), RowOrder::BottomFirst).ok());
                EXPECT_EQ(bytes, e.bytes) << pass << ", 8-bit, frame " << frame.frame;
                EXPECT_EQ(topFirst, e.topFirst) << pass << ", 8-bit top first, frame " << frame.frame;
                EXPECT_EQ(floats, e.floats) << pass << ", floats, frame " << frame.frame;
                return true;
            });
            ASSERT_TRUE(done.ok()) << done.error().text();
        }
        EXPECT_EQ(handed, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    });
}

// TOYHOST_EGL_PLATFORM chooses a headless session's EGL platform as it does the CLI's.
TEST(LibraryApi, TheEnvironmentChoosesTheEglPlatform) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/pingpong-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    const char* before = std::getenv("TOYHOST_EGL_PLATFORM");
    const std::string kept = before ? before : "";
    auto backendWith = [&](const char* platform) -> Result<std::string> {
        setenv("TOYHOST_EGL_PLATFORM", platform, 1);
        Result<std::string> backend = Error("not run", Code::Internal);
        runOnGlThread([&] {
            Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe);
            if (session) backend = (*session)->backend();
            else backend = session.error();
        });
        return backend;
    };
    Result<std::string> wrong = backendWith("wayland");
    Result<std::string> surfaceless = backendWith("surfaceless");
    Result<std::string> device = backendWith("device");
    if (before) setenv("TOYHOST_EGL_PLATFORM", kept.c_str(), 1);
    else unsetenv("TOYHOST_EGL_PLATFORM");

    ASSERT_FALSE(wrong.ok()) << "TOYHOST_EGL_PLATFORM=wayland was not refused";
    EXPECT_EQ(wrong.error().first().code, Code::Usage);
    EXPECT_NE(wrong.error().text().find("TOYHOST_EGL_PLATFORM=wayland"), std::string::npos) << wrong.error().text();
    ASSERT_TRUE(surfaceless.ok()) << surfaceless.error().text();
    EXPECT_EQ(surfaceless->rfind("EGL surfaceless;", 0), 0u) << *surfaceless;
    // The device platform, where this machine's EGL has it (Mesa's has, on llvmpipe too). Skipped
    // only where it is absent (support/EglDevicePlatform.h says exactly when); where EGL lists a
    // device, a session that does not start there fails.
    if (std::optional<std::string> absent = eglDevicePlatformAbsence()) GTEST_SKIP() << *absent;
    ASSERT_TRUE(device.ok()) << "EGL lists a device, but: " << device.error().text();
    EXPECT_EQ(device->rfind("EGL device", 0), 0u) << "TOYHOST_EGL_PLATFORM=device was not used: " << *device;
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
    Session::RenderRequest request;
    request.frames = 2;
    request.pass = "Buffer A";
    std::vector<float> rendered(a.size());
    ASSERT_TRUE((*session)
                    ->render(request,
                             [&](const Session::RenderedFrame& frame) {
                                 return frame.read(std::span<float>(rendered), RowOrder::BottomFirst).ok();
                             })
                    .ok());
    EXPECT_EQ(state(), before) << "rendering into memory changed the caller's state";
    ASSERT_TRUE((*session)->read("Buffer A", a, RowOrder::BottomFirst).ok());
    EXPECT_EQ(rendered, a) << "the last frame handed over differs from read()";
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

// A reload planned on another thread (prepareReload) and applied on the session's GL thread: the
// new code needs the browser-style expansion (a cpp child), and with no cpp to be found while
// the reload is applied, it still compiles: the GL thread only compiled.
TEST(LibraryApi, AReloadIsPlannedOffTheGlThreadAndAppliedOnIt) {
    const fs::path dir = freshOutputDir("library-api/prepared-reload");
    writeFile(dir / "manifest.json", R"({"passes": {"Image": {"source": "image.glsl"}}})");
    writeFile(dir / "image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.25, 0.0, 0.0, 1.0); }\n");
    Result<Shadertoy> first = Shadertoy::load(dir);
    ASSERT_TRUE(first.ok()) << first.error().text();
    writeFile(dir / "image.glsl", "#define NEG(x) -x\nvoid mainImage(out vec4 c, in vec2 f) {\n"
                                  "  c = vec4(NEG(-.5), 0.0, 0.0, 1.0); }\n");
    Result<Shadertoy> second = Shadertoy::load(dir);
    ASSERT_TRUE(second.ok()) << second.error().text();
    SessionSettings settings;
    settings.width = 1;
    settings.height = 1;

    const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
    Result<Reloaded> reloaded = Error("not applied", Code::Internal);
    Result<Reloaded> again = Error("not applied", Code::Internal);
    std::vector<float> pixel(4);
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*first, settings);
        if (!session) {
            ADD_FAILURE() << session.error().text();
            return;
        }
        // Planned on a thread of its own while the session stays on this one.
        std::optional<PreparedReload> prepared;
        std::thread planner([&] { prepared.emplace((*session)->prepareReload(*second)); });
        planner.join();
        ::setenv("PATH", "", 1);  // no cpp while the GL thread applies the reload
        reloaded = (*session)->reload(std::move(*prepared));
        ::setenv("PATH", path.c_str(), 1);
        again = (*session)->reload(std::move(*prepared));
        if (Status stepped = (*session)->step(); !stepped) ADD_FAILURE() << stepped.error().text();
        if (Status read = (*session)->read("Image", std::span<float>(pixel)); !read) ADD_FAILURE() << read.error().text();
    });
    ASSERT_TRUE(reloaded.ok()) << reloaded.error().text();
    EXPECT_TRUE(reloaded->applied);
    EXPECT_TRUE(reloaded->problems.empty()) << (reloaded->problems.empty() ? "" : reloaded->problems[0].message);
    EXPECT_NEAR(pixel[0], 0.5f, 1.0f / 255) << "the new code runs";
    ASSERT_FALSE(again.ok()) << "a PreparedReload is used once";
    EXPECT_EQ(again.error().first().code, Code::Usage);
}

}  // namespace
}  // namespace toyhost::testing

namespace toyhost::testing {
namespace {

// The library's settings are checked as a run's options are, and the error names the setting
// (Diagnostic::field), not a CLI flag.
TEST(LibraryApi, ImpossibleSettingsAreRefusedNamingTheSetting) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/timeline-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    struct Case {
        const char* setting;
        SessionSettings settings;
    };
    std::vector<Case> cases;
    SessionSettings s;
    s.fps = -5;
    cases.push_back({"fps", s});
    s = {};
    s.fps = std::numeric_limits<double>::quiet_NaN();
    cases.push_back({"fps", s});
    s = {};
    s.width = -1;
    s.height = 10;
    cases.push_back({"size", s});
    s = {};
    s.startTime = std::numeric_limits<double>::infinity();
    cases.push_back({"start_time", s});
    s = {};
    s.frameTimeout = -1;
    cases.push_back({"frame_timeout", s});
    // Given values are checked, never taken for "the default": 0 is an error like any other.
    s = {};
    s.width = 0;
    s.height = 0;
    cases.push_back({"size", s});
    s = {};
    s.width = 16;  // without a height
    cases.push_back({"size", s});
    s = {};
    s.fps = 0;
    cases.push_back({"fps", s});
    s = {};
    s.date = "";
    cases.push_back({"date", s});
    s = {};
    s.date = "2026-02-30";
    cases.push_back({"date", s});
    s = {};
    s.compileTimeout = 0.01;
    cases.push_back({"compile_timeout", s});
    runOnGlThread([&] {
        for (const Case& c : cases) {
            Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe, c.settings);
            ASSERT_FALSE(session.ok()) << c.setting;
            EXPECT_EQ(session.error().category(), Category::Usage) << session.error().text();
            EXPECT_EQ(session.error().first().field, c.setting) << session.error().text();
            EXPECT_EQ(session.error().text().find("--"), std::string::npos) << session.error().text();
        }
    });
}

// One check, one message: width = 0 through the library is refused as `run --size 0x0` is, the CLI
// showing its flag where the library names the setting.
TEST(LibraryApi, AGivenZeroSizeIsRefusedAsTheClisIs) {
    const std::filesystem::path probe = sourceDir() / "shadertoys/timeline-probe";
    Result<Shadertoy> shadertoy = Shadertoy::load(probe);
    ASSERT_TRUE(shadertoy.ok()) << shadertoy.error().text();
    SessionSettings settings;
    settings.width = 0;
    settings.height = 0;
    std::optional<Error> refused;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*shadertoy, settings);
        if (!session) refused = session.error();
    });
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->first().field, "size");
    EXPECT_EQ(refused->first().message, "canvas size 0x0 is not between 1x1 and 16384x16384");
    const CommandResult cli = runToyhost("run " + probe.string() + " --headless --size 0x0 --frames 1");
    EXPECT_EQ(cli.exitCode, 2) << cli.output;
    EXPECT_NE(cli.output.find("--size: " + refused->first().message), std::string::npos) << cli.output;
}

// Once a defect (issue 46): a Session beyond 16384 a side was planned as a tiled still and drew,
// read and handed over one 1024-wide tile (width() said 1024), so compareShadertoys said "equal"
// for frames that differed beyond it. Frames read in memory are one target: refused, naming size.
TEST(LibraryApi, ACanvasBeyondOneTargetIsRefusedNotCutToATile) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/tile-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    SessionSettings settings;
    settings.width = 20000;
    settings.height = 100;
    std::optional<Error> refused, compared;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*probe, settings);
        if (!session) refused = session.error();
        CompareSettings both;
        both.session = settings;
        both.frames = 1;
        Result<CompareReport> report = compareShadertoys(*probe, *probe, both);
        if (!report) compared = report.error();
    });
    ASSERT_TRUE(refused.has_value()) << "a 20000x100 session was made";
    EXPECT_EQ(refused->category(), Category::Usage);
    EXPECT_EQ(refused->first().field, "size");
    EXPECT_NE(refused->first().message.find("at most 16384x16384"), std::string::npos) << refused->text();
    ASSERT_TRUE(compared.has_value()) << "a 20000x100 comparison was answered";
    EXPECT_EQ(compared->first().message, refused->first().message);
}

// setChannel(): a program's pixels in a channel, in either row order, and the refusals that come
// back as data (the Python tests cover formats, filtering and reloads).
TEST(LibraryApi, SetChannelShowsAnArrayInEitherRowOrder) {
    const fs::path dir = freshOutputDir("library-api/set-channel");
    writeFile(dir / "image.glsl", "void mainImage(out vec4 c, in vec2 p) { c = texelFetch(iChannel0, ivec2(p), 0); }\n");
    Result<Shadertoy> toy = Shadertoy::load(dir / "image.glsl");
    ASSERT_TRUE(toy.ok()) << toy.error().text();
    SessionSettings settings;
    settings.width = 3;
    settings.height = 2;
    runOnGlThread([&] {
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*toy, settings);
        ASSERT_TRUE(made.ok()) << made.error().text();
        Session& session = **made;
        // Two rows of three grey levels: row 0 = 10, 20, 30; row 1 = 40, 50, 60.
        const std::vector<std::uint8_t> rows{10, 20, 30, 40, 50, 60};
        ChannelArray array;
        array.width = 3;
        array.height = 2;
        array.components = 1;
        array.data = rows.data();
        array.bytes = rows.size();
        std::vector<std::uint8_t> shown(3 * 2 * 4);
        for (RowOrder order : {RowOrder::TopFirst, RowOrder::BottomFirst}) {
            array.order = order;
            ASSERT_TRUE(session.setChannel("Image", 0, array).ok());
            ASSERT_TRUE(session.step().ok());
            ASSERT_TRUE(session.read("Image", shown, RowOrder::TopFirst).ok());
            // The first row read (the top) is row 0 when the array is top first, row 1 otherwise.
            const std::uint8_t top = order == RowOrder::TopFirst ? 10 : 40;
            EXPECT_EQ(shown[0], top);
            EXPECT_EQ(shown[4], top + 10);
            EXPECT_EQ(shown[12], order == RowOrder::TopFirst ? 40 : 10);
            EXPECT_EQ(shown[1], 0) << "one component samples as (r, 0, 0, 1)";
        }
        array.bytes = 5;
        Status shortData = session.setChannel("Image", 0, array);
        ASSERT_FALSE(shortData.ok());
        EXPECT_EQ(shortData.error().first().code, Code::Usage);
        EXPECT_NE(shortData.error().text().find("Image iChannel0: 5 bytes for an array of shape (2, 3, 1) uint8, which needs 6"),
                  std::string::npos)
            << shortData.error().text();
        array.bytes = 6;
        EXPECT_FALSE(session.setChannel("Buffer A", 0, array).ok()) << "no Buffer A";
        EXPECT_FALSE(session.setChannel("Image", 4, array).ok()) << "channels are 0..3";
        // From another thread: refused, as every call is.
        Status elsewhere = okStatus();
        std::thread([&] { elsewhere = session.setChannel("Image", 0, array); }).join();
        EXPECT_FALSE(elsewhere.ok());
    });
}

}  // namespace
}  // namespace toyhost::testing
