#include "render/CubeTarget.h"

#include <cmath>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

const std::array<std::array<float, 12>, 6>& cubeFaceCorners() {
    static const std::array<std::array<float, 12>, 6> corners{{
        {1, 1, 1, 1, 1, -1, 1, -1, -1, 1, -1, 1},          // +X
        {-1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1},      // -X
        {-1, 1, -1, 1, 1, -1, 1, 1, 1, -1, 1, 1},          // +Y
        {-1, -1, 1, 1, -1, 1, 1, -1, -1, -1, -1, -1},      // -Y
        {-1, 1, 1, 1, 1, 1, 1, -1, 1, -1, -1, 1},          // +Z
        {1, 1, -1, -1, 1, -1, -1, -1, -1, 1, -1, -1},      // -Z
    }};
    return corners;
}

Result<CubeTarget> CubeTarget::create(int size, bool mipmapped) {
    if (size < 1 || size > maxTextureSize())
        return Error("GL: a " + std::to_string(size) + "x" + std::to_string(size) +
                         " cubemap face is larger than this GL allows",
                     Code::GlTextureSize);
    CubeTarget target;
    target.size_ = size;
    target.mipmapped_ = mipmapped;
    const int levels = mipmapped ? 1 + static_cast<int>(std::floor(std::log2(size))) : 1;
    for (Slot& slot : target.slots_) {
        slot.texture = makeTexture();
        glBindTexture(GL_TEXTURE_CUBE_MAP, slot.texture.id());
        glTexStorage2D(GL_TEXTURE_CUBE_MAP, levels, GL_RGBA16F, size, size);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
        if (GLenum error = glGetError(); error != GL_NO_ERROR)
            return Error(std::string("GL: allocating the Cube A cubemap failed: ") + glErrorName(error), Code::GlTexture);
        for (int face = 0; face < 6; ++face) {
            slot.faces[face] = makeFramebuffer();
            glBindFramebuffer(GL_FRAMEBUFFER, slot.faces[face].id());
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + face,
                                   slot.texture.id(), 0);
            if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                return Error("GL: a Cube A face cannot be rendered to (RGBA16F framebuffer incomplete)", Code::GlTexture);
            }
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    target.clear();
    return target;
}

void CubeTarget::clear() {
    const GLfloat zero[4] = {0, 0, 0, 0};
    for (int slot = 0; slot < 2; ++slot) {
        for (int face = 0; face < 6; ++face) {
            glBindFramebuffer(GL_FRAMEBUFFER, slots_[slot].faces[face].id());
            glClearBufferfv(GL_COLOR, 0, zero);
        }
        generateMipmaps(slot);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void CubeTarget::generateMipmaps(int slot) const {
    if (!mipmapped_) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_CUBE_MAP, slots_[slot].texture.id());
    glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
}

}  // namespace toyhost
