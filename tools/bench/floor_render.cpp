// floor_render: the smallest honest way to render one Shadertoy Image pass headless, written
// straight against EGL, OpenGL ES 3 and libpng. It deliberately does NOT use the toyhost runtime
// library, so it serves two purposes:
//   - an independent check of toyhost's output (tests/gl/test_floor_match.cpp compares the two);
//   - the performance floor: per frame it sets the uniforms and draws one triangle, nothing else,
//     so benchmarks can tell how much time toyhost adds on top of the shader itself.
// Usage: floor_render SHADER.glsl --size WxH --time T [--frames N] [--fps F] [--out file.png]
//                     [--finish-each-frame]
// Prints `floor: frames=N seconds_total=X ms_per_frame=Y first_frame_ms=Z` on stdout; errors go
// to stderr with exit code 1. Channels are left unbound (texture unit 0..3, nothing attached).
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES3/gl3.h>
#include <png.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

[[noreturn]] void fail(const std::string& message) {
    std::fprintf(stderr, "floor_render: %s\n", message.c_str());
    std::exit(1);
}

const char* const kUsage =
    "usage: floor_render SHADER.glsl --size WxH --time T [--frames N] [--fps F] "
    "[--out file.png] [--finish-each-frame]";

struct Options {
    std::string shaderPath;
    int width = 0, height = 0;
    double startTime = 0.0;
    bool timeGiven = false;
    int frames = 1;
    double fps = 60.0;
    std::string outPath;  // empty: no readback, no PNG
    bool finishEachFrame = false;
};

Options parseArguments(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) fail(arg + " needs a value\n" + kUsage);
            return argv[++i];
        };
        char x = 0, extra = 0;
        if (arg == "--size") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%d%c%d%c", &o.width, &x, &o.height, &extra) != 3 || x != 'x' ||
                o.width <= 0 || o.height <= 0)
                fail("--size must be WxH with positive integers, got '" + v + "'");
        } else if (arg == "--time") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%lf%c", &o.startTime, &extra) != 1) fail("bad --time '" + v + "'");
            o.timeGiven = true;
        } else if (arg == "--frames") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%d%c", &o.frames, &extra) != 1 || o.frames < 1)
                fail("--frames must be a positive integer, got '" + v + "'");
        } else if (arg == "--fps") {
            const std::string v = value();
            if (std::sscanf(v.c_str(), "%lf%c", &o.fps, &extra) != 1 || !(o.fps > 0.0))
                fail("--fps must be a positive number, got '" + v + "'");
        } else if (arg == "--out") {
            o.outPath = value();
        } else if (arg == "--finish-each-frame") {
            o.finishEachFrame = true;
        } else if (!arg.empty() && arg[0] != '-' && o.shaderPath.empty()) {
            o.shaderPath = arg;
        } else {
            fail("unexpected argument '" + arg + "'\n" + kUsage);
        }
    }
    if (o.shaderPath.empty() || o.width == 0 || !o.timeGiven) fail(kUsage);
    return o;
}

// The Shadertoy (WebGL2) Image-pass header, written out by hand: the point of this program is
// not to share toyhost's shader assembly. `#line 1` makes compile errors point at the user's file.
const char* const kFragmentHeader =
    "#version 300 es\n"
    "precision highp float;\n"
    "precision highp int;\n"
    "precision mediump sampler3D;\n"
    // Desktop GPUs (where shadertoys are written) compute lowp/mediump in 32 bits, Mesa in 16.
    // toyhost promotes every precision to highp for that reason; do the same so the two compare.
    "precision highp sampler2D; precision highp samplerCube; precision highp sampler3D;\n"
    "#define lowp highp\n"
    "#define mediump highp\n"
    "#define HW_PERFORMANCE 1\n"
    "uniform vec3 iResolution;\n"
    "uniform float iTime;\n"
    "uniform float iChannelTime[4];\n"
    "uniform vec4 iMouse;\n"
    "uniform vec4 iDate;\n"
    "uniform float iSampleRate;\n"
    "uniform vec3 iChannelResolution[4];\n"
    "uniform int iFrame;\n"
    "uniform float iTimeDelta;\n"
    "uniform float iFrameRate;\n"
    "uniform sampler2D iChannel0;\n"
    "uniform sampler2D iChannel1;\n"
    "uniform sampler2D iChannel2;\n"
    "uniform sampler2D iChannel3;\n"
    "void mainImage(out vec4 c, in vec2 f);\n"
    "out vec4 floorOutColor;\n"
    "void main() {\n"
    "    vec4 color = vec4(0.0, 0.0, 0.0, 1.0);\n"
    "    mainImage(color, gl_FragCoord.xy);\n"
    "    floorOutColor = vec4(color.xyz, 1.0);\n"
    "}\n"
    "#line 1\n";

// One triangle that covers the viewport: vertices (-1,-1), (3,-1), (-1,3), from gl_VertexID alone,
// so no buffers or attributes are needed.
const char* const kVertexShader =
    "#version 300 es\n"
    "void main() {\n"
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot read shader '" + path + "'");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

const char* eglErrorText() {
    switch (eglGetError()) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "other EGL error";
    }
}

bool hasExtension(const char* list, const char* name) {
    const size_t n = std::strlen(name);
    for (const char* p = list; p && (p = std::strstr(p, name)); p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

// An OpenGL ES 3.0 context current without any surface: on Mesa's surfaceless platform, or with
// TOYHOST_EGL_PLATFORM=device on the first EGL device (EGL_EXT_platform_device: NVIDIA's driver),
// as toyhost chooses with the same variable.
void createContext() {
    const char* platformName = std::getenv("TOYHOST_EGL_PLATFORM");
    const bool device = platformName && std::string(platformName) == "device";
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) fail("EGL: eglGetPlatformDisplayEXT is missing");
    EGLDisplay display = EGL_NO_DISPLAY;
    if (device) {
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT first = nullptr;
        EGLint devices = 0;
        if (!queryDevices || !queryDevices(1, &first, &devices) || devices < 1) fail("EGL: no EGL device found");
        display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, first, nullptr);
    } else {
        if (!hasExtension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless"))
            fail("EGL: EGL_MESA_platform_surfaceless is not available (TOYHOST_EGL_PLATFORM=device for a GPU)");
        display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr))
        fail(std::string("EGL: cannot initialize the display: ") + eglErrorText());
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context"))
        fail("EGL: EGL_KHR_surfaceless_context is not supported");
    if (!eglBindAPI(EGL_OPENGL_ES_API)) fail(std::string("EGL: eglBindAPI: ") + eglErrorText());
    // EGL_SURFACE_TYPE 0: the config never backs a surface; we render into our own FBO.
    const EGLint configAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES3_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0)
        fail(std::string("EGL: no OpenGL ES 3 config: ") + eglErrorText());
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) fail(std::string("EGL: eglCreateContext: ") + eglErrorText());
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
        fail(std::string("EGL: eglMakeCurrent: ") + eglErrorText());
    // The process exits right after rendering; the driver releases the context then.
}

GLuint compileShader(GLenum type, const std::vector<const char*>& sources, const std::string& what) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, static_cast<GLsizei>(sources.size()), sources.data(), nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[8192] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        fail(what + ": compile error:\n" + log);
    }
    return shader;
}

GLuint buildProgram(const std::string& shaderPath, const std::string& userCode) {
    GLuint program = glCreateProgram();
    glAttachShader(program, compileShader(GL_VERTEX_SHADER, {kVertexShader}, "fullscreen vertex shader"));
    glAttachShader(program, compileShader(GL_FRAGMENT_SHADER, {kFragmentHeader, userCode.c_str()}, shaderPath));
    glLinkProgram(program);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[8192] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        fail(shaderPath + ": link error:\n" + log);
    }
    return program;
}

// Writes 8-bit RGBA; `bottomUp` is glReadPixels' order, the PNG wants the top row first.
void writePng(const std::string& path, int width, int height, const std::vector<unsigned char>& bottomUp) {
    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) fail("cannot write '" + path + "'");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info || setjmp(png_jmpbuf(png))) fail("libpng failed writing '" + path + "'");
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const size_t rowBytes = static_cast<size_t>(width) * 4;
    for (int y = height - 1; y >= 0; --y) png_write_row(png, bottomUp.data() + y * rowBytes);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    if (std::fclose(file) != 0) fail("cannot finish writing '" + path + "'");
}

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const Clock::time_point processStart = Clock::now();
    const Options o = parseArguments(argc, argv);
    const std::string userCode = readFile(o.shaderPath);

    createContext();
    const GLuint program = buildProgram(o.shaderPath, userCode);

    // The render target: one RGBA8 renderbuffer, like the 8-bit canvas the player shows.
    GLuint colour = 0, framebuffer = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, o.width, o.height);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        fail("the RGBA8 framebuffer is incomplete");
    glViewport(0, 0, o.width, o.height);
    glUseProgram(program);

    // Uniforms that never change: set once. Unknown names (optimised out) get location -1,
    // which glUniform* ignores. iMouse, iDate, iChannelTime, iChannelResolution stay 0.
    glUniform3f(glGetUniformLocation(program, "iResolution"), float(o.width), float(o.height), 1.0f);
    glUniform1f(glGetUniformLocation(program, "iSampleRate"), 44100.0f);
    for (int i = 0; i < 4; ++i)
        glUniform1i(glGetUniformLocation(program, ("iChannel" + std::to_string(i)).c_str()), i);
    const GLint timeLocation = glGetUniformLocation(program, "iTime");
    const GLint timeDeltaLocation = glGetUniformLocation(program, "iTimeDelta");
    const GLint frameRateLocation = glGetUniformLocation(program, "iFrameRate");
    const GLint frameLocation = glGetUniformLocation(program, "iFrame");

    // Without --finish-each-frame the draws queue up and llvmpipe may skip work: a draw whose
    // opaque shader covers a whole tile (with no depth buffer) discards the queued commands of that
    // tile, so frames overwritten before any sync are never shaded. ms_per_frame then understates
    // the shading cost; use --finish-each-frame (or compare against a host that also syncs).
    double firstFrameMs = 0.0;
    const Clock::time_point loopStart = Clock::now();
    for (int n = 0; n < o.frames; ++n) {
        glUniform1f(timeLocation, static_cast<float>(o.startTime + n / o.fps));
        glUniform1f(timeDeltaLocation, static_cast<float>(1.0 / o.fps));
        glUniform1f(frameRateLocation, static_cast<float>(o.fps));
        glUniform1i(frameLocation, n);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (n == 0 || o.finishEachFrame) glFinish();
        if (n == 0) firstFrameMs = millisecondsSince(processStart);
    }
    glFinish();
    const double totalSeconds = millisecondsSince(loopStart) / 1000.0;
    if (GLenum error = glGetError(); error != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", error);
        fail(std::string("GL error ") + code + " while rendering");
    }

    if (!o.outPath.empty()) {
        std::vector<unsigned char> pixels(static_cast<size_t>(o.width) * o.height * 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, o.width, o.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        writePng(o.outPath, o.width, o.height, pixels);
    }

    std::printf("floor: frames=%d seconds_total=%.6f ms_per_frame=%.3f first_frame_ms=%.3f\n", o.frames,
                totalSeconds, totalSeconds * 1000.0 / o.frames, firstFrameMs);
    return 0;
}
