#include "gl/ShaderProgram.h"

#include <vector>

namespace toyhost {

namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram) glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> text(static_cast<size_t>(length > 0 ? length : 1), '\0');
    if (isProgram) glGetProgramInfoLog(object, length, nullptr, text.data());
    else glGetShaderInfoLog(object, length, nullptr, text.data());
    return std::string(text.data());
}

Result<GlShader> compile(GLenum stage, const std::string& text) {
    GlShader shader(glCreateShader(stage));
    const char* source = text.c_str();
    glShaderSource(shader.id(), 1, &source, nullptr);
    glCompileShader(shader.id());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) return Error{infoLog(shader.id(), false)};
    return shader;
}

}  // namespace

Result<GlProgram> buildProgram(const AssembledShader& fragment, const ProgramSources& names) {
    Result<GlShader> vertex = compile(GL_VERTEX_SHADER, fullscreenVertexShader());
    if (!vertex) return Error{names.passLabel + ": internal vertex shader failed: " + vertex.error().message};
    Result<GlShader> pixel = compile(GL_FRAGMENT_SHADER, fragment.text);
    if (!pixel)
        return Error{names.passLabel + ": shader compile failed\n" +
                     translateCompilerLog(fragment, pixel.error().message, names.commonFile, names.passFile)};

    GlProgram program(glCreateProgram());
    glAttachShader(program.id(), vertex->id());
    glAttachShader(program.id(), pixel->id());
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        return Error{names.passLabel + " (" + names.passFile + "): shader link failed\n" +
                     translateCompilerLog(fragment, infoLog(program.id(), true), names.commonFile,
                                          names.passFile)};
    return program;
}

}  // namespace toyhost
