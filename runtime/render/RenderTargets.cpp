#include "render/RenderTargets.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

namespace {
std::string hex(unsigned value) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%04X", value);
    return text;
}
}  // namespace

Result<RenderTexture> createRenderTexture(int width, int height, GLenum internalFormat, bool mipmapped) {
    const int limit = maxTextureSize();
    if (width < 1 || height < 1 || width > limit || height > limit)
        return Error("GL: a " + std::to_string(width) + "x" + std::to_string(height) +
                         " render target is outside what this GL allows (1 .. GL_MAX_TEXTURE_SIZE " +
                         std::to_string(limit) + ")",
                     Code::GlTextureSize);
    RenderTexture target{makeTexture(), makeFramebuffer(), width, height, 1};
    target.levels = mipmapped ? 1 + static_cast<int>(std::floor(std::log2(std::max(width, height)))) : 1;
    glBindTexture(GL_TEXTURE_2D, target.texture.id());
    glTexStorage2D(GL_TEXTURE_2D, target.levels, internalFormat, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: allocating a ") + std::to_string(width) + "x" + std::to_string(height) +
                         " render target failed: " + glErrorName(error),
                     Code::GlTexture);

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.id(), 0);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return Error("GL: a " + std::to_string(width) + "x" + std::to_string(height) +
                         " render target is incomplete (status " + hex(status) + ")",
                     Code::GlTexture);
    }
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: creating a render target failed: ") + glErrorName(error), Code::GlTexture);
    return target;
}

Result<PingPongTarget> PingPongTarget::create(int width, int height, bool mipmapped, const TextureAllocator& allocate) {
    PingPongTarget target;
    target.width_ = width;
    target.height_ = height;
    target.mipmapped_ = mipmapped;
    for (RenderTexture& slot : target.slots_) {
        Result<RenderTexture> made = allocate(width, height, GL_RGBA32F, mipmapped);
        if (!made) return made.error();
        slot = std::move(*made);
    }
    // Level 0 is cleared; the other levels must read as zero too (the frame-0 state).
    for (int i = 0; i < 2; ++i) target.generateMipmaps(i);
    return target;
}

void PingPongTarget::clear() {
    const GLfloat zero[4] = {0, 0, 0, 0};
    for (int i = 0; i < 2; ++i) {
        glBindFramebuffer(GL_FRAMEBUFFER, slots_[i].framebuffer.id());
        glClearBufferfv(GL_COLOR, 0, zero);
        generateMipmaps(i);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PingPongTarget::copyContentFrom(const PingPongTarget& old) {
    const int copyW = std::min(width_, old.width_), copyH = std::min(height_, old.height_);
    for (int i = 0; i < 2; ++i) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, old.slots_[i].framebuffer.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, slots_[i].framebuffer.id());
        glBlitFramebuffer(0, 0, copyW, copyH, 0, 0, copyW, copyH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (int i = 0; i < 2; ++i) generateMipmaps(i);
}

void PingPongTarget::generateMipmaps(int slot) const {
    if (!mipmapped_) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, slots_[slot].texture.id());
    glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace toyhost
