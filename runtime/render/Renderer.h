// Renderer: executes a PassGraph. Owns the programs (one per pass, uniform locations looked up
// once), the buffers' ping-pong targets, the channel textures and the Image target; which slot a
// channel reads comes from the graph and the step counter it is given. The Player
// (player/Player.h) owns the renderer and decides when to render, resize or rebuild; nothing
// else drives it. Needs a current GL context for its whole life.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "core/Defaults.h"
#include "core/Result.h"
#include "gl/GpuActivity.h"
#include "graph/PassGraph.h"
#include "image/Image.h"
#include "manifest/ManifestDesc.h"
#include "media/ChannelMedia.h"
#include "render/RenderTargets.h"
#include "render/SampleAccumulator.h"
#include "shader/PassSource.h"

namespace toyhost {

struct RendererDesc {
    // The context's published activity (GlContext::gpuActivity()): compiling publishes the pass,
    // each draw is followed (when the context is watched), and every readback and finish() below
    // publishes the pass the GPU is still drawing around its wait, so callers never do. Required.
    GpuActivity* gpu = nullptr;
    int width = 0;                 // canvas size, already validated
    int height = 0;
    // The Image pass renders into RGBA8 (what the screen shows) unless its raw float output is
    // wanted (EXR capture of Image, tests).
    bool floatImageTarget = false;
    // Frames may draw the Image pass several times and average the draws (renderFrame's `draws`):
    // the float targets are allocated once here; `average` says how (render/SampleAccumulator.h;
    // its floatTarget follows floatImageTarget).
    bool accumulate = false;
    SampleAverage average;
    // iResolution when the targets are a tile of a larger canvas (a tiled still: drawImageAt
    // places them); 0: the targets' own size.
    int resolutionWidth = 0;
    int resolutionHeight = 0;
    TextureAllocator allocate;     // empty: createRenderTexture
};

// Per-frame uniform values; the caller owns the clock and the inputs.
struct FrameUniforms {
    int frame = 0;
    // iTime. Double: the frame of a video channel is floor(time * fps) (a 30 fps clip at --fps 30
    // shows frame N at frame N only with the exact time); narrowed to float only for glUniform.
    double time = 0;
    float timeDelta = 0;
    float frameRate = static_cast<float>(defaults::kFps);
    glm::vec4 mouse{0};
    glm::vec4 date{0};
};

// One draw of the Image pass when a frame averages several (timing/SamplePattern.h): fragCoord's
// offset in pixels and the iTime and iDate of that draw; the other uniforms are the frame's.
struct ImageDraw {
    glm::vec2 offset{0.0f};
    double time = 0;
    glm::vec4 date{0};
};

// Where a pass's latest output is, for readback and presenting.
struct PassOutput {
    unsigned int framebuffer = 0;
    unsigned int texture = 0;
    int width = 0;
    int height = 0;
    PixelFormat format = PixelFormat::Rgba8;
};

class Renderer {
public:
    // `sources`: each pass's prepared texts, in manifest.passes' order (PlayerPlan::sources).
    static Result<std::unique_ptr<Renderer>> create(const ManifestDesc& manifest, const PassGraph& graph,
                                                    const RendererDesc& desc, const ChannelMedia& images,
                                                    std::span<const PassSource> sources);
    ~Renderer();

    // Runs every buffer, then Image when `renderImage`. `step` picks the ping-pong slots
    // (graph/PassGraph.h); it must go up by one per call. With more than one of `draws` (the
    // renderer made with `accumulate`), Image is drawn once per draw and the Image target gets
    // their average; buffers and Cube A still run once, with `uniforms`.
    void renderFrame(const FrameUniforms& uniforms, std::uint64_t step, bool renderImage = true,
                     std::span<const ImageDraw> draws = {});

    // Draws the last frame's Image pass again (its uniforms and draws) with the Image target's
    // corner at `origin` of the canvas (fragCoord moved by it): a tile of a still larger than the
    // target. The origin stays for later frames.
    void drawImageAt(glm::vec2 origin);

    // Shows `texture` (2D, width x height, owned by the caller: render/ArrayTextures.h) in channel
    // `channel` of `pass`, sampled with `sampler`, until the renderer is rebuilt; iChannelResolution
    // follows. The caller checks that the channel may take it (Player::setChannelArray).
    void bindPicture(PassId pass, int channel, GLuint texture, int width, int height, const SamplerDesc& sampler);

    // New keyboard texels (256*3 bytes, row 0 first); call only when they changed.
    void updateKeyboard(std::span<const std::uint8_t> texels);

    // Resizes the canvas: every target is allocated first, and only when all of them exist is
    // the buffer content copied (bottom-left) and the old targets released. On failure nothing
    // changed.
    Status resize(int width, int height);
    // Every buffer's both slots to zero (a restart: frame 0 starts from cleared buffers).
    void clearBuffers();

    // Recompiles pass `index` (graph order) from `pass`'s prepared texts; on failure the old
    // program stays.
    Status replaceProgram(std::size_t index, const ManifestDesc& manifest, const PassDesc& pass,
                          const PassSource& source);
    // For a renderer rebuilt from a changed manifest: takes the content of every buffer that
    // `old` also has (moving the textures when their layout is the same, else copying).
    void takeBuffersFrom(Renderer& old);

    // One slot of buffer `index` (0..3, must exist) as RGBA floats, rows bottom first; and the
    // same written back (level 0; its mip levels are rebuilt). For checkpoints.
    bool hasBuffer(int index) const;
    void readBufferSlot(int index, int slot, std::vector<float>& out) const;
    void writeBufferSlot(int index, int slot, std::span<const float> rgba);

    // A notice per pass that compiled only after preprocessing as browsers do (from create and
    // replaceProgram), for the driver to print.
    const std::vector<Diagnostic>& compileNotices() const;

    int width() const { return width_; }
    int height() const { return height_; }

    // Waits until the GPU has executed everything submitted (glFinish). Runs call it once at the
    // end so that their measured time includes the GPU's work; never per frame.
    void finish();
    // Submits what was drawn without waiting (glFlush), so that the GPU works on it while the
    // caller goes on (the library's step(): llvmpipe would start a frame only once it is read).
    void submit();

    // A pass's latest output (a buffer's last rendered slot, or the Image target).
    PassOutput output(PassId pass) const;

    // Synchronous readbacks of a pass's latest output, rows bottom first: as floats, or as the
    // bytes a UNORM8 target holds (clamped and rounded).
    void readRgba32f(PassId pass, std::vector<float>& out) const;
    void readRgba8(PassId pass, std::vector<std::uint8_t>& out) const;

    // Cube A (must exist): one face (0..5, GL order +X, -X, +Y, -Y, +Z, -Z) of its latest output
    // as RGBA floats, rows bottom first (row 0 is the face's t = 0); `size` gets the face side.
    bool hasCube() const;
    void readCubeFace(int face, std::vector<float>& out, int& size) const;
    // Both slots of Cube A for checkpoints: a slot's six faces one after the other (RGBA floats,
    // rows bottom first); and the same written back (its mip levels rebuilt).
    void readCubeSlot(int slot, std::vector<float>& out, int& size) const;
    void writeCubeSlot(int slot, std::span<const float> faces);

    struct Impl;

private:
    explicit Renderer(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace toyhost
