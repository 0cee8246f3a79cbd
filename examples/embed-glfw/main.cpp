// embed-glfw: an application that owns its window, GL context, shader, quad and mouse, and has
// toyhost render a shadertoy into a texture on its context (Session::createOnCurrentContext),
// which it draws on its own quad inside a frame of its own colour. The GLFW context is OpenGL ES 3
// on EGL (toyhost adopts the current EGL context).
//
//   embed-glfw SHADERTOY [--size WxH] [--frames N] [--fps F] [--wait-events] [--check]
//
// Without --fps it runs in real time (iTime from glfwGetTime); without --frames until the window
// is closed (or Esc). --wait-events renders a frame only when input arrives (as an editor would).
// Drag with the left button in the quad: the shadertoy gets iMouse in its canvas pixels.
// --check (tests/CMakeLists.txt runs it under Xvfb): every step must leave the app's GL state as it
// was (GlStateSnapshot before and after), and the last frame on the quad, read back from the app's
// framebuffer, must equal a headless render of the same frames with the same mouse events
// (PSNR inf). Exit 0 when all holds, 1 otherwise.
#include <GLES3/gl3.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <toyhost/Compare.h>
#include <toyhost/Session.h>
#include <vector>

#include "GlStateSnapshot.h"

namespace {

constexpr int kMargin = 16;  // the app's own frame around the quad, in pixels

const char* kVertexShader = R"(#version 300 es
layout(location = 0) in vec2 position;
out vec2 uv;
void main() { uv = position * 0.5 + 0.5; gl_Position = vec4(position, 0.0, 1.0); })";

const char* kFragmentShader = R"(#version 300 es
precision highp float;
uniform sampler2D shadertoy;
in vec2 uv;
out vec4 colour;
void main() { colour = texture(shadertoy, uv); })";

GLuint compile(GLenum type, const char* source) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    return shader;
}

// What the app knows about its mouse, in shadertoy canvas pixels (origin bottom-left), and the
// events it has not handed to the session yet.
struct Mouse {
    int canvasWidth = 0, canvasHeight = 0;
    std::vector<toyhost::InputEvent> pending;
    bool held = false;

    // The window's cursor (top-left origin) to the quad's canvas pixels, as the site computes them.
    void at(double cursorX, double cursorY, toyhost::InputEvent::Type what) {
        const float x = std::floor(static_cast<float>(cursorX - kMargin));
        const float y = std::floor(static_cast<float>(canvasHeight - (cursorY - kMargin)));
        if (what == toyhost::InputEvent::Type::MouseDown) pending.push_back(toyhost::InputEvent::mouseDown(x, y));
        else if (what == toyhost::InputEvent::Type::MouseUp) pending.push_back(toyhost::InputEvent::mouseUp());
        else if (held) pending.push_back(toyhost::InputEvent::mouseMove(x, y));
    }
};

void onButton(GLFWwindow* window, int button, int action, int) {
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    auto* mouse = static_cast<Mouse*>(glfwGetWindowUserPointer(window));
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    mouse->held = action == GLFW_PRESS;
    mouse->at(x, y, action == GLFW_PRESS ? toyhost::InputEvent::Type::MouseDown : toyhost::InputEvent::Type::MouseUp);
}

void onCursor(GLFWwindow* window, double x, double y) {
    static_cast<Mouse*>(glfwGetWindowUserPointer(window))->at(x, y, toyhost::InputEvent::Type::MouseMove);
}

void onKey(GLFWwindow* window, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

int fail(const std::string& what) {
    std::fprintf(stderr, "embed-glfw: %s\n", what.c_str());
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    std::string path;
    int width = 320, height = 180, frames = 0;
    double fps = 0;
    bool check = false, waitEvents = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--size" && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
        else if (arg == "--frames" && i + 1 < argc) frames = std::atoi(argv[++i]);
        else if (arg == "--fps" && i + 1 < argc) fps = std::atof(argv[++i]);
        else if (arg == "--check") check = true;
        else if (arg == "--wait-events") waitEvents = true;
        else path = arg;
    }
    if (path.empty() || width <= 0 || height <= 0) return fail("usage: embed-glfw SHADERTOY [--size WxH] [--frames N] [--fps F] [--check]");
    if (check && fps <= 0) return fail("--check needs --fps (a repeatable run)");

    // The application's window and context: OpenGL ES 3.0 on EGL.
    if (!glfwInit()) return fail("glfwInit failed");
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(width + 2 * kMargin, height + 2 * kMargin, "embed-glfw", nullptr, nullptr);
    if (!window) return fail("cannot open an OpenGL ES 3 window on EGL");
    glfwMakeContextCurrent(window);
    glfwSwapInterval(check ? 0 : 1);
    Mouse mouse;
    mouse.canvasWidth = width;
    mouse.canvasHeight = height;
    glfwSetWindowUserPointer(window, &mouse);
    glfwSetMouseButtonCallback(window, onButton);
    glfwSetCursorPosCallback(window, onCursor);
    glfwSetKeyCallback(window, onKey);

    // The application's own GL objects: a program, a quad, a sampler.
    GLuint program = glCreateProgram();
    glAttachShader(program, compile(GL_VERTEX_SHADER, kVertexShader));
    glAttachShader(program, compile(GL_FRAGMENT_SHADER, kFragmentShader));
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) return fail("the app's own shader does not link");
    const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    GLuint vao = 0, vbo = 0, sampler = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glGenSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // The app's state, set once and relied on from frame to frame: toyhost must leave it alone.
    constexpr int kUnit = 2;
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "shadertoy"), kUnit);
    glActiveTexture(GL_TEXTURE0 + kUnit);
    glBindSampler(kUnit, sampler);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_CULL_FACE);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    // toyhost on the application's context.
    toyhost::Result<toyhost::Shadertoy> shadertoy = toyhost::Shadertoy::load(path);
    if (!shadertoy) return fail(shadertoy.error().text());
    toyhost::SessionSettings settings;
    settings.width = width;
    settings.height = height;
    settings.fps = fps;
    if (check) settings.date = "2026-01-01T00:00:00";
    const GlStateSnapshot beforeCreation = check ? GlStateSnapshot::capture() : GlStateSnapshot{};
    auto session = toyhost::Session::createOnCurrentContext(*shadertoy, settings);
    if (!session) return fail(session.error().text());
    std::string stateChanges;
    if (check) {
        const std::string changed = beforeCreation.differencesTo(GlStateSnapshot::capture());
        if (!changed.empty()) stateChanges = "creating the session changed the app's GL state:\n" + changed;
    }

    std::vector<std::vector<toyhost::InputEvent>> eventsOfFrame;  // kept for --check's replay
    std::vector<std::uint8_t> shown(static_cast<std::size_t>(width) * height * 4);
    double last = glfwGetTime();
    for (int frame = 0; (frames == 0 || frame < frames) && !glfwWindowShouldClose(window); ++frame) {
        waitEvents && frame > 0 ? glfwWaitEvents() : glfwPollEvents();
        std::vector<toyhost::InputEvent> events = std::move(mouse.pending);
        mouse.pending.clear();
        const GlStateSnapshot before = check ? GlStateSnapshot::capture() : GlStateSnapshot{};
        toyhost::Status stepped = toyhost::okStatus();
        if (fps > 0) {
            stepped = (*session)->step(events);
        } else {
            const double now = glfwGetTime();
            stepped = (*session)->stepAt(now, now - last, 1.0 / std::max(now - last, 1e-6), events);
            last = now;
        }
        if (!stepped) return fail(stepped.error().text());
        if (check) {
            const std::string changed = before.differencesTo(GlStateSnapshot::capture());
            if (!changed.empty() && stateChanges.empty())
                stateChanges = "frame " + std::to_string(frame) + ": toyhost's step changed the app's GL state:\n" + changed;
            eventsOfFrame.push_back(events);
        }

        // The app's own drawing: its frame colour, then the shadertoy's texture on its quad.
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width + 2 * kMargin, height + 2 * kMargin);
        glClear(GL_COLOR_BUFFER_BIT);
        glViewport(kMargin, kMargin, width, height);
        glBindTexture(GL_TEXTURE_2D, (*session)->imageTexture());
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
        if (check)
            glReadPixels(kMargin, kMargin, width, height, GL_RGBA, GL_UNSIGNED_BYTE, shown.data());  // bottom row first
        glfwSwapBuffers(window);
    }
    glBindTexture(GL_TEXTURE_2D, 0);  // toyhost's texture goes with the session
    const GlStateSnapshot beforeDestruction = check ? GlStateSnapshot::capture() : GlStateSnapshot{};
    session->reset();  // toyhost's GL objects go while the app's context is current
    if (check && stateChanges.empty()) {
        const std::string changed = beforeDestruction.differencesTo(GlStateSnapshot::capture());
        if (!changed.empty()) stateChanges = "destroying the session changed the app's GL state:\n" + changed;
    }

    int code = 0;
    if (check) {
        if (!stateChanges.empty()) {
            std::fprintf(stderr, "embed-glfw: %s", stateChanges.c_str());
            code = 1;
        }
        // The same frames headless, with the same events on the same frames, and without events.
        std::size_t mouseEvents = 0;
        for (const auto& events : eventsOfFrame) mouseEvents += events.size();
        auto render = [&](bool withEvents, std::vector<std::uint8_t>& pixels) -> toyhost::Status {
            auto headless = toyhost::Session::createHeadless(*shadertoy, settings);
            if (!headless) return headless.error();
            for (const auto& events : eventsOfFrame)
                if (toyhost::Status s = (*headless)->step(withEvents ? std::span<const toyhost::InputEvent>(events)
                                                                         : std::span<const toyhost::InputEvent>()); !s) return s;
            pixels.resize(shown.size());
            return (*headless)->read("Image", pixels, toyhost::RowOrder::BottomFirst);
        };
        std::vector<std::uint8_t> expected, untouched;
        if (toyhost::Status s = render(true, expected); !s) return fail(s.error().text());
        // A frame of one colour would prove little about where the quad's pixels come from.
        bool varied = false;
        for (std::size_t i = 4; i < expected.size() && !varied; i += 4) varied = std::memcmp(&expected[i], &expected[0], 3) != 0;
        if (!varied) return fail("the headless frame is one colour: choose a shadertoy with a picture for --check");
        auto d = toyhost::compareImages(shown, expected, width, height, 3);
        if (!d) return fail(d.error().text());
        const int rendered = static_cast<int>(eventsOfFrame.size());
        std::printf("embed-glfw: %d frames, %zu mouse events; the quad against a headless render of frame %d: PSNR %s dB, "
                    "max diff %d\n",
                    rendered, mouseEvents, rendered - 1, std::isinf(d->psnr) ? "inf" : std::to_string(d->psnr).c_str(),
                    d->maxDiff);
        if (d->maxDiff != 0) code = 1;
        if (mouseEvents > 0) {
            if (toyhost::Status s = render(false, untouched); !s) return fail(s.error().text());
            const bool changed = untouched != expected;
            std::printf("embed-glfw: the mouse %s the picture\n", changed ? "changed" : "did not change");
        }
        if (code == 0) std::printf("embed-glfw: the app's GL state was unchanged by creating the session, every step and destroying it\n");
    }
    glfwDestroyWindow(window);
    glfwTerminate();
    return code;
}
