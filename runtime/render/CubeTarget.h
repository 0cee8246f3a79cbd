// CubeTarget: the Cube A pass's output, two cubemap textures (ping-pong like a buffer's two
// slots), six square RGBA16F faces each with a framebuffer per face, linear/clamp as on the site.
// Needs a current GL context.
#pragma once

#include <array>

#include "core/Result.h"
#include "gl/GlObjects.h"

namespace toyhost {

// The corner directions of each face, GL face order (+X, -X, +Y, -Y, +Z, -Z): c0..c3 as the
// site's Paint_Cubemap passes them in unCorners[0..3] (unCorners[4] is the apex, 0,0,0).
const std::array<std::array<float, 12>, 6>& cubeFaceCorners();

class CubeTarget {
public:
    static Result<CubeTarget> create(int size, bool mipmapped);

    GLuint texture(int slot) const { return slots_[slot].texture.id(); }
    GLuint faceFramebuffer(int slot, int face) const { return slots_[slot].faces[face].id(); }
    int size() const { return size_; }
    bool mipmapped() const { return mipmapped_; }

    void clear();                            // both slots, every face, to zero
    void generateMipmaps(int slot) const;    // no-op unless mipmapped

private:
    struct Slot {
        GlTexture texture;
        std::array<GlFramebuffer, 6> faces;
    };
    std::array<Slot, 2> slots_;
    int size_ = 0;
    bool mipmapped_ = false;
};

}  // namespace toyhost
