#include "gl/GlContext.h"

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

}  // namespace toyhost
