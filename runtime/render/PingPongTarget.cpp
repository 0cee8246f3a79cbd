#include "render/PingPongTarget.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "gl/GlContext.h"

namespace toyhost {

Result<RenderTexture> createRenderTexture(int width, int height, GLenum internalFormat, bool mipmapped) {
    RenderTexture target{makeTexture(), makeFramebuffer()};
    const int levels = mipmapped ? 1 + static_cast<int>(std::floor(std::log2(std::max(width, height)))) : 1;
    glBindTexture(GL_TEXTURE_2D, target.texture.id());
    glTexStorage2D(GL_TEXTURE_2D, levels, internalFormat, width, height);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindTexture(GL_TEXTURE_2D, 0);

    glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.texture.id(), 0);
    GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return Error{"GL: render target " + std::to_string(width) + "x" + std::to_string(height) +
                     " is incomplete (status 0x" + std::to_string(status) + ")"};
    }
    const GLfloat zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error{std::string("GL: creating a render target failed: ") + glErrorName(error)};
    return target;
}

Result<PingPongTarget> PingPongTarget::create(int width, int height, bool mipmapped) {
    PingPongTarget target;
    target.width_ = width;
    target.height_ = height;
    target.mipmapped_ = mipmapped;
    for (RenderTexture& slot : target.slots_) {
        Result<RenderTexture> made = createRenderTexture(width, height, GL_RGBA32F, mipmapped);
        if (!made) return made.error();
        slot = std::move(*made);
    }
    return target;
}

Status PingPongTarget::resize(int width, int height) {
    Result<PingPongTarget> next = create(width, height, mipmapped_);
    if (!next) return next.error();
    const int copyW = std::min(width, width_), copyH = std::min(height, height_);
    for (int i = 0; i < 2; ++i) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, slots_[i].framebuffer.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, next->slots_[i].framebuffer.id());
        glBlitFramebuffer(0, 0, copyW, copyH, 0, 0, copyW, copyH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    *this = std::move(*next);
    return okStatus();
}

}  // namespace toyhost
