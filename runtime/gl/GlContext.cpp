#include "gl/GlContext.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <fcntl.h>
#include <unistd.h>

#include <GLES3/gl3.h>
#include <cstring>

namespace toyhost {

namespace {
bool hasExtension(const char* name) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
        if (ext && std::strcmp(ext, name) == 0) return true;
    }
    return false;
}
}  // namespace

Status checkRequiredGlFeatures() {
    for (const char* ext : {"GL_EXT_color_buffer_float", "GL_OES_texture_float_linear"})
        if (!hasExtension(ext))
            return Error(std::string("GL: the driver lacks ") + ext + ", which Shadertoy's float buffers need",
                         Code::GlFeature);
    return okStatus();
}

int maxTextureSize() {
    GLint size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
    return size;
}

const char* glErrorName(unsigned int error) {
    switch (error) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    }
    return "unknown GL error";
}

namespace {
bool zeroInitSetByToyhost = false;
}  // namespace

void requestWebGlDriverBehaviour() {
    if (std::getenv("glsl_zero_init")) return;
    setenv("glsl_zero_init", "true", 0);
    zeroInitSetByToyhost = true;
}

namespace {
constexpr std::string_view kAnnouncement = "ATTENTION: default value of option glsl_zero_init overridden by environment.";
}  // namespace

std::string DriverStartupQuiet::withoutAnnouncement(std::string_view text) {
    std::string kept;
    while (!text.empty()) {
        const std::size_t end = text.find('\n');
        const std::string_view line = text.substr(0, end == std::string_view::npos ? text.size() : end + 1);
        if (line.substr(0, kAnnouncement.size()) != kAnnouncement) kept += line;
        text.remove_prefix(line.size());
    }
    return kept;
}

DriverStartupQuiet::DriverStartupQuiet() {
    // Whoever set it (toyhost, or a parent toyhost whose environment this process inherited),
    // Mesa announces the override on stderr.
    const char* zeroInit = std::getenv("glsl_zero_init");
    if (!zeroInitSetByToyhost && !(zeroInit && std::string_view(zeroInit) == "true")) return;
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) return;
    // A writer never blocks on the pipe (another thread writing a lot meanwhile loses the excess
    // rather than waiting for a reader that runs only afterwards).
    ::fcntl(fds[1], F_SETFL, O_NONBLOCK);
    ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
    std::fflush(stderr);
    savedStderr_ = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
    if (savedStderr_ < 0 || ::dup2(fds[1], STDERR_FILENO) < 0) {
        ::close(fds[0]);
        ::close(fds[1]);
        if (savedStderr_ >= 0) ::close(savedStderr_);
        savedStderr_ = -1;
        return;
    }
    ::close(fds[1]);
    pipe_ = fds[0];
}

DriverStartupQuiet::~DriverStartupQuiet() {
    if (savedStderr_ < 0) return;
    std::fflush(stderr);
    ::dup2(savedStderr_, STDERR_FILENO);  // the pipe's last write end closes here
    ::close(savedStderr_);
    std::string text;
    char chunk[4096];
    for (ssize_t n; (n = ::read(pipe_, chunk, sizeof chunk)) > 0;) text.append(chunk, static_cast<std::size_t>(n));
    ::close(pipe_);
    const std::string kept = withoutAnnouncement(text);
    for (std::size_t done = 0; done < kept.size();) {
        const ssize_t n = ::write(STDERR_FILENO, kept.data() + done, kept.size() - done);
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
}

}  // namespace toyhost
