#include "gl/ShaderProgram.h"

#include <vector>

#include "core/DivisionOverflowTrap.h"

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

// The compiled shader, or an empty one with `log` set.
GlShader compile(GLenum stage, const std::string& text, std::string& log) {
    GlShader shader(glCreateShader(stage));
    const char* source = text.c_str();
    glShaderSource(shader.id(), 1, &source, nullptr);
    {
        const DivisionOverflowTrap folding;  // INT_MIN / -1 in a constant expression (Mesa folds with idiv)
        glCompileShader(shader.id());
    }
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        log = infoLog(shader.id(), false);
        return GlShader();
    }
    return shader;
}

}  // namespace

ProgramBuild buildProgram(const std::string& vertexText, const std::string& fragmentText) {
    ProgramBuild build;
    GlShader vertex = compile(GL_VERTEX_SHADER, vertexText, build.log);
    if (!vertex) {
        build.failedStage = ProgramBuild::Stage::Vertex;
        return build;
    }
    GlShader fragment = compile(GL_FRAGMENT_SHADER, fragmentText, build.log);
    if (!fragment) {
        build.failedStage = ProgramBuild::Stage::Fragment;
        return build;
    }
    GlProgram program(glCreateProgram());
    glAttachShader(program.id(), vertex.id());
    glAttachShader(program.id(), fragment.id());
    {
        const DivisionOverflowTrap folding;  // linking folds constants again
        glLinkProgram(program.id());
    }
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        build.failedStage = ProgramBuild::Stage::Link;
        build.log = infoLog(program.id(), true);
        return build;
    }
    build.program = std::move(program);
    build.ok = true;
    return build;
}

}  // namespace toyhost
