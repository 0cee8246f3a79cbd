// OverlayRenderer: draws Dear ImGui's draw lists into the default framebuffer with OpenGL ES 3,
// for the window's overlay (drivers/window/Overlay.h). Our own rather than Debian's opengl3
// backend, which is built for desktop GL (it loads libGL itself and touches state ES lacks).
// Textures other than the font atlas are a pass's output: drawn opaque, and texels that are NaN
// or infinite in a loud magenta. The GL state the renderer relies on is restored after each draw.
// Needs the window's GL context current, and the ImGui context whose fonts it uploads.
#pragma once

#include <memory>

#include "core/Result.h"
#include "gl/GlObjects.h"

struct ImDrawData;

namespace toyhost {

class OverlayRenderer {
public:
    // Compiles its program and uploads the current ImGui context's font atlas (its texture id is
    // set on the atlas).
    static Result<std::unique_ptr<OverlayRenderer>> create();

    void render(const ImDrawData& data, int framebufferW, int framebufferH);

private:
    OverlayRenderer() = default;
    GlProgram program_;
    int scaleLocation_ = -1, pictureLocation_ = -1, textureLocation_ = -1;
    GlVertexArray vertexArray_;
    GlBuffer vertices_, indices_;
    GlTexture font_;
    GlSampler sampler_;
};

}  // namespace toyhost
