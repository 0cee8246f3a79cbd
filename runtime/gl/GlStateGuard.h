// GlStateGuard: saves the GL state toyhost's renderer touches when it lives and restores it when it
// ends, for sessions that render on a context that belongs to someone else (the library API's
// createOnCurrentContext): framebuffer bindings, program, viewport, active texture, the 2D, cube
// and 3D textures and samplers of the units toyhost binds, vertex array, array and pixel buffer
// bindings, blending, depth and scissor tests, cull face, pixel-store alignments and the clear
// colour. Needs the context current.
#pragma once

#include <array>

namespace toyhost {

class GlStateGuard {
public:
    GlStateGuard();
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

    static constexpr int kUnits = 4;  // iChannel0..3

private:
    int drawFramebuffer_ = 0, readFramebuffer_ = 0, program_ = 0, activeTexture_ = 0, vertexArray_ = 0;
    int arrayBuffer_ = 0, packBuffer_ = 0, unpackBuffer_ = 0, packAlignment_ = 4, unpackAlignment_ = 4;
    std::array<int, 4> viewport_{};
    std::array<float, 4> clearColour_{};
    std::array<std::array<int, 3>, kUnits> textures_{};  // 2D, cube, 3D per unit
    std::array<int, kUnits> samplers_{};
    bool blend_ = false, depthTest_ = false, scissorTest_ = false, cullFace_ = false;
};

}  // namespace toyhost
