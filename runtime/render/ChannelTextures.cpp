#include "render/ChannelTextures.h"

#include <vector>

#include "image/MipChain.h"

namespace toyhost {

void uploadMipLevels(GLenum target, const std::uint8_t* level0, int width, int height) {
    const std::span<const std::uint8_t> pixels(level0, static_cast<std::size_t>(width) * height * 4);
    const std::vector<MipLevel> levels = boxMipChain(pixels, width, height);
    for (std::size_t l = 0; l < levels.size(); ++l)
        glTexImage2D(target, static_cast<GLint>(l + 1), GL_RGBA8, levels[l].width, levels[l].height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, levels[l].rgba.data());
}

InputTexture uploadImage(const Image8& image, const SamplerDesc& sampler) {
    InputTexture out{makeTexture(), image.width, image.height};
    // GL's first row is t = 0. Images in memory are bottom row first, so with vflip (Shadertoy's
    // default) they upload as they are, the top at t = 1; without vflip the browser uploads the
    // file's rows in file order (top first), which puts the top at t = 0.
    std::vector<std::uint8_t> flipped;
    const std::uint8_t* pixels = image.rgba.data();
    if (!sampler.vflip) {
        copyFlipped(std::span<const std::uint8_t>(image.rgba), image.width, image.height, flipped);
        pixels = flipped.data();
    }
    glBindTexture(GL_TEXTURE_2D, out.texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    if (sampler.filter == Filter::Mipmap) uploadMipLevels(GL_TEXTURE_2D, pixels, image.width, image.height);
    else glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    return out;
}

KeyboardTexture::KeyboardTexture() : texture_(makeTexture()) {
    const std::vector<std::uint8_t> zeros(kWidth * kHeight, 0);
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kWidth, kHeight, 0, GL_RED, GL_UNSIGNED_BYTE, zeros.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void KeyboardTexture::update(std::span<const std::uint8_t> texels) {
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kWidth, kHeight, GL_RED, GL_UNSIGNED_BYTE, texels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

SamplerSet::SamplerSet() {
    const GLenum minFilters[3] = {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    const GLenum magFilters[3] = {GL_NEAREST, GL_LINEAR, GL_LINEAR};
    const GLenum wraps[2] = {GL_CLAMP_TO_EDGE, GL_REPEAT};
    for (int f = 0; f < 3; ++f)
        for (int w = 0; w < 2; ++w) {
            GlSampler& s = samplers_[f][w];
            s = makeSampler();
            glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, minFilters[f]);
            glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, magFilters[f]);
            glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, wraps[w]);
            glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, wraps[w]);
            glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_R, wraps[w]);
        }
}

}  // namespace toyhost
