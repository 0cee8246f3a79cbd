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

DriverStartupQuiet::DriverStartupQuiet() {
    // Whoever set it (toyhost, or a parent toyhost whose environment this process inherited),
    // Mesa announces the override on stderr.
    const char* zeroInit = std::getenv("glsl_zero_init");
    if (!zeroInitSetByToyhost && !(zeroInit && std::string_view(zeroInit) == "true")) return;
    std::fflush(stderr);
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null < 0) return;
    savedStderr_ = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
    if (savedStderr_ >= 0) dup2(null, STDERR_FILENO);
    close(null);
}

DriverStartupQuiet::~DriverStartupQuiet() {
    if (savedStderr_ < 0) return;
    std::fflush(stderr);
    dup2(savedStderr_, STDERR_FILENO);
    close(savedStderr_);
}

}  // namespace toyhost
