// Renderer: executes a PassGraph each frame. Owns the programs (one per pass, uniform locations
// looked up once), the buffers' ping-pong targets, the channel textures and the Image target.
// Needs a current GL context for its whole life.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/vec4.hpp>
#include <memory>
#include <span>
#include <vector>

#include "core/Result.h"
#include "graph/PassGraph.h"
#include "manifest/ManifestDesc.h"
#include "media/Image.h"

namespace toyhost {

struct RendererOptions {
    int width = 800;
    int height = 450;
    // The Image pass renders into RGBA8 (what the screen shows) unless its raw float output is
    // wanted (EXR capture of Image).
    bool floatImageTarget = false;
};

// Per-frame uniform values; the caller owns the clock and the inputs.
struct FrameUniforms {
    int frame = 0;
    float time = 0;
    float timeDelta = 0;
    float frameRate = 60;
    glm::vec4 mouse{0};
    glm::vec4 date{0};
};

// Supplies the pixels of an image-file or stock-media channel (rows top first).
using ImageProvider = std::function<Result<Image8>(const ChannelDesc&)>;

class Renderer {
public:
    static Result<std::unique_ptr<Renderer>> create(const ManifestDesc& manifest, const PassGraph& graph,
                                                    const RendererOptions& options,
                                                    const ImageProvider& images);
    ~Renderer();

    // Runs every buffer, then Image when `renderImage` (headless runs skip Image on frames
    // nobody captures). Frames must be rendered in order, starting at 0.
    void renderFrame(const FrameUniforms& uniforms, bool renderImage = true);

    // New keyboard texels (256*3 bytes, row 0 first); call only when they changed.
    void updateKeyboard(std::span<const std::uint8_t> texels);

    // Resizes the canvas; buffer content survives in the bottom-left corner.
    Status resize(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Waits until the GPU has executed everything submitted (glFinish). Runs call it once at the
    // end so that their measured time includes the GPU's work; never per frame.
    void finish();

    // True when a pass's output texture holds floats (buffers, and the Image target when it was
    // created with floatImageTarget); false for the RGBA8 Image target.
    bool outputIsFloat(PassId pass) const;

    // Synchronous readbacks of the last rendered frame, rows bottom first.
    void readImageRgba8(std::vector<std::uint8_t>& out) const;
    // A buffer's last rendered texture, or the Image target, as float RGBA.
    void readRgba32f(PassId pass, std::vector<float>& out) const;
    // The framebuffer holding a pass's latest output (for readback and presenting).
    unsigned int outputFramebuffer(PassId pass) const;

    struct Impl;

private:
    explicit Renderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace toyhost
