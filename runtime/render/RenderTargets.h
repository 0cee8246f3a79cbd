// Render targets: a colour texture with the framebuffer that renders into it, and a buffer's two
// canvas-sized RGBA32F textures (ping-pong, see graph/PassGraph.h for which slot is read).
// Needs a current GL context.
#pragma once

#include <array>
#include <functional>

#include "core/Result.h"
#include "gl/GlObjects.h"

namespace toyhost {

// A colour texture with the framebuffer that renders into its level 0.
struct RenderTexture {
    GlTexture texture;
    GlFramebuffer framebuffer;
    int width = 0;
    int height = 0;
    int levels = 1;  // mip levels allocated
};

// Creates a width x height texture of `internalFormat` (with a full mip chain when `mipmapped`),
// nearest/clamp like Shadertoy's buffers, attached to a new framebuffer and cleared to zero.
Result<RenderTexture> createRenderTexture(int width, int height, GLenum internalFormat, bool mipmapped);

// How the renderer allocates its targets: createRenderTexture, unless a test injects failures.
using TextureAllocator = std::function<Result<RenderTexture>(int width, int height, GLenum internalFormat,
                                                             bool mipmapped)>;

class PingPongTarget {
public:
    static Result<PingPongTarget> create(int width, int height, bool mipmapped, const TextureAllocator& allocate);

    const RenderTexture& slot(int index) const { return slots_[index]; }
    int width() const { return width_; }
    int height() const { return height_; }
    bool mipmapped() const { return mipmapped_; }

    // Both slots to zero (level 0; the mip levels are rebuilt).
    void clear();
    // Copies `old`'s content into the bottom-left min(old, new) region of both slots (slot i from
    // old slot i), as Shadertoy does when the canvas is resized; the rest stays zero. Every mip
    // level is rebuilt from the new level 0.
    void copyContentFrom(const PingPongTarget& old);
    // Rebuilds the mip chain of one slot from its level 0 (no-op unless mipmapped).
    void generateMipmaps(int slot) const;

private:
    std::array<RenderTexture, 2> slots_;
    int width_ = 0;
    int height_ = 0;
    bool mipmapped_ = false;
};

}  // namespace toyhost
