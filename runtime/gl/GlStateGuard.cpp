#include "gl/GlStateGuard.h"

#include <GLES3/gl3.h>

namespace toyhost {

namespace {
int integer(GLenum name) {
    GLint value = 0;
    glGetIntegerv(name, &value);
    return value;
}
void enable(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }
// A name saved at the start that toyhost deleted meanwhile (the caller had one of toyhost's own
// objects bound, such as the Image texture when the session goes) is restored as 0, as GL's
// deletion leaves it: binding the freed name again would make a new, empty object of that name.
GLuint alive(int name, GLboolean (*exists)(GLuint)) {
    const GLuint id = static_cast<GLuint>(name);
    return id != 0 && exists(id) ? id : 0;
}
}  // namespace

GlStateGuard::GlStateGuard() {
    drawFramebuffer_ = integer(GL_DRAW_FRAMEBUFFER_BINDING);
    readFramebuffer_ = integer(GL_READ_FRAMEBUFFER_BINDING);
    program_ = integer(GL_CURRENT_PROGRAM);
    activeTexture_ = integer(GL_ACTIVE_TEXTURE);
    vertexArray_ = integer(GL_VERTEX_ARRAY_BINDING);
    arrayBuffer_ = integer(GL_ARRAY_BUFFER_BINDING);
    packBuffer_ = integer(GL_PIXEL_PACK_BUFFER_BINDING);
    unpackBuffer_ = integer(GL_PIXEL_UNPACK_BUFFER_BINDING);
    packAlignment_ = integer(GL_PACK_ALIGNMENT);
    unpackAlignment_ = integer(GL_UNPACK_ALIGNMENT);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColour_.data());
    for (int unit = 0; unit < kUnits; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        textures_[unit] = {integer(GL_TEXTURE_BINDING_2D), integer(GL_TEXTURE_BINDING_CUBE_MAP),
                           integer(GL_TEXTURE_BINDING_3D)};
        samplers_[unit] = integer(GL_SAMPLER_BINDING);
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    blend_ = glIsEnabled(GL_BLEND);
    depthTest_ = glIsEnabled(GL_DEPTH_TEST);
    scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
    cullFace_ = glIsEnabled(GL_CULL_FACE);
}

GlStateGuard::~GlStateGuard() {
    for (int unit = 0; unit < kUnits; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, alive(textures_[unit][0], glIsTexture));
        glBindTexture(GL_TEXTURE_CUBE_MAP, alive(textures_[unit][1], glIsTexture));
        glBindTexture(GL_TEXTURE_3D, alive(textures_[unit][2], glIsTexture));
        glBindSampler(unit, alive(samplers_[unit], glIsSampler));
    }
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, alive(drawFramebuffer_, glIsFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, alive(readFramebuffer_, glIsFramebuffer));
    glUseProgram(alive(program_, glIsProgram));
    glBindVertexArray(alive(vertexArray_, glIsVertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, alive(arrayBuffer_, glIsBuffer));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, alive(packBuffer_, glIsBuffer));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, alive(unpackBuffer_, glIsBuffer));
    glPixelStorei(GL_PACK_ALIGNMENT, packAlignment_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, unpackAlignment_);
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    glClearColor(clearColour_[0], clearColour_[1], clearColour_[2], clearColour_[3]);
    enable(GL_BLEND, blend_);
    enable(GL_DEPTH_TEST, depthTest_);
    enable(GL_SCISSOR_TEST, scissorTest_);
    enable(GL_CULL_FACE, cullFace_);
}

}  // namespace toyhost
