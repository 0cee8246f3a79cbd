// PingPongTarget: a buffer's two canvas-sized RGBA32F textures with their framebuffers, cleared
// to zero at creation; frame n renders into slot n % 2 (see graph/PassGraph.h).
// Needs a current GL context.
#pragma once

#include <array>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

// A colour texture with the framebuffer that renders into its level 0.
struct RenderTexture {
    GlTexture texture;
    GlFramebuffer framebuffer;
};

// Creates a width x height texture of `internalFormat` (with a full mip chain when `mipmapped`),
// nearest/clamp like Shadertoy's buffers, attached to a new framebuffer and cleared to zero.
Result<RenderTexture> createRenderTexture(int width, int height, GLenum internalFormat, bool mipmapped);

class PingPongTarget {
public:
    static Result<PingPongTarget> create(int width, int height, bool mipmapped);

    const RenderTexture& slot(int index) const { return slots_[index]; }
    int width() const { return width_; }
    int height() const { return height_; }
    bool mipmapped() const { return mipmapped_; }

    // New textures at the new size holding the old content in their bottom-left
    // min(old, new) region (both slots), as Shadertoy does when the canvas is resized.
    Status resize(int width, int height);

private:
    std::array<RenderTexture, 2> slots_;
    int width_ = 0;
    int height_ = 0;
    bool mipmapped_ = false;
};

}  // namespace toyhost
