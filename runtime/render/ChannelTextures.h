// GL textures for the inputs a channel can bind besides buffers: image files and stock media
// (RGBA8, flipped at upload when vflip is set, mipmaps when sampled with `mipmap`) and the
// 256x3 keyboard texture; plus the sampler objects that carry each channel's filter and wrap.
// Needs a current GL context.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "gl/GlObjects.h"
#include "manifest/ManifestDesc.h"
#include "image/Image.h"

namespace toyhost {

struct InputTexture {
    GlTexture texture;
    int width = 0;
    int height = 0;
};

// The texture target a channel binds to, as the header declares its sampler.
inline GLenum textureTarget(SamplerType type) {
    return type == SamplerType::SamplerCube ? GL_TEXTURE_CUBE_MAP
           : type == SamplerType::Sampler3D ? GL_TEXTURE_3D
                                            : GL_TEXTURE_2D;
}

// Uploads `image` (rows bottom first) as RGBA8. With `vflip` the picture's top row ends up at
// t = 1, as WebGL's UNPACK_FLIP_Y does; without it the file's first row (its top) is at t = 0.
InputTexture uploadImage(const Image8& image, const SamplerDesc& sampler);

// Uploads levels 1..n of an RGBA8 level 0 (bound to `target`: GL_TEXTURE_2D or a cube face)
// built on the CPU with an exact box filter (image/MipChain.h), instead of glGenerateMipmap.
void uploadMipLevels(GLenum target, const std::uint8_t* level0, int width, int height);

class KeyboardTexture {
public:
    static constexpr int kWidth = 256;
    static constexpr int kHeight = 3;
    KeyboardTexture();
    // 256*3 bytes, row 0 (held) first.
    void update(std::span<const std::uint8_t> texels);
    GLuint id() const { return texture_.id(); }

private:
    GlTexture texture_;
};

// One GL sampler object per (filter, wrap), shared by every channel.
class SamplerSet {
public:
    SamplerSet();
    GLuint get(const SamplerDesc& desc) const {
        return samplers_[static_cast<int>(desc.filter)][static_cast<int>(desc.wrap)].id();
    }

private:
    std::array<std::array<GlSampler, 2>, 3> samplers_;
};

}  // namespace toyhost
