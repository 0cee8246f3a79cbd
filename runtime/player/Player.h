// Player: the one engine every driver runs (the headless run, the window, the compatibility
// runner, the tests). It owns a running shadertoy: the pass graph, the renderer with its buffers,
// the mouse and keyboard state the shader sees, and the frame counters (graph/FrameSequence.h).
// Drivers own the clock and the input sources and call step() once per frame; they also decide
// when to resize, restart or reload. Needs its GL context current on the calling thread; it
// holds the context, so its GL objects are destroyed before the context by ownership.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/Result.h"
#include "gl/GlContext.h"
#include "graph/FrameSequence.h"
#include "input/InputEvent.h"
#include "player/PlayerDesc.h"
#include "render/ArrayTextures.h"
#include "render/Renderer.h"
#include "timing/FrameTime.h"

namespace toyhost {

struct ReloadReport {
    // The passes, channels or images (their pixels, not only their files' names) changed: the
    // renderer was rebuilt (when `applied`), carrying over the content of every buffer the new
    // manifest still has.
    bool structureChanged = false;
    bool applied = false;                 // the new manifest (or some of its passes) runs now
    std::vector<std::string> recompiled;  // passes whose new code runs now
    // Passes that did not compile: each keeps its last good program (after a structure change,
    // the whole old shadertoy keeps running).
    std::vector<Diagnostic> problems;
};

// Everything a running shadertoy holds that the next frames depend on, besides its code and
// images: the frame counters, the inputs and both slots of every buffer. A checkpoint is this
// plus what the run needs to continue (run/Checkpoint.h).
struct PlayerState {
    int frame = 0;                 // iFrame of the next frame
    std::uint64_t step = 0;        // its ping-pong step
    int width = 0, height = 0;     // canvas
    MouseState::Saved mouse;
    std::array<std::uint8_t, KeyboardState::kWidth * KeyboardState::kHeight> keyboard{};
    struct Buffer {
        int index = 0;                        // 0..3 = A..D
        std::array<std::vector<float>, 2> slots;  // RGBA32F, rows bottom first
    };
    std::vector<Buffer> buffers;
    // Cube A's two slots, each its six faces (GL order) of cubeSize^2 RGBA floats one after the
    // other; cubeSize 0 when the shadertoy has no Cube A.
    int cubeSize = 0;
    std::array<std::vector<float>, 2> cube;
};

class Player {
public:
    // Makes `context` current and builds everything; every shader error is reported at once.
    static Result<std::unique_ptr<Player>> create(std::shared_ptr<GlContext> context, PlayerPlan plan,
                                                  PlayerDesc desc = {});
    ~Player();
    Player(const Player&) = delete;
    Player& operator=(const Player&) = delete;

    // Applies `events` (in order) to the mouse and keyboard, renders frame iFrame = frame() (every
    // buffer, then Image unless `renderImage` is false: nothing reads Image but the driver), then
    // ends the frame for the inputs (the click and went-down signals last one frame) and advances.
    // With desc.sampling asking for more than one draw, Image is drawn at each sample's offset and
    // time inside the frame (timing/SamplePattern.h) and averaged; buffers and Cube A run once.
    void step(const FrameTime& time, std::span<const InputEvent> events = {}, bool renderImage = true);

    int frame() const { return sequence_.frame(); }  // iFrame of the next frame
    // Renders the last frame again, at `time`, with the code that runs now (a paused window after a
    // reload): the same iFrame, every pass, no new input. Buffers take one more step (each reads
    // its own last output), as on the site, whose compile repaints every pass. False, and nothing
    // rendered, when no frame was rendered since the start or a restart.
    bool repaint(const FrameTime& time);

    // New canvas size; buffers keep their content bottom-left, iFrame goes on. All or nothing: on
    // failure (a size GL cannot hold) the old size and content stay.
    Status resize(int width, int height);
    // iFrame back to 0 and every buffer cleared, as the site's restart does; mouse and keyboard
    // state stay. The driver resets its clock.
    void restart();
    // Switches to `next` (made by planPlayer, possibly on another thread): see ReloadReport.
    ReloadReport reload(PlayerPlan next);

    // Shows `pixels` in channel `channel` (0..3) of `pass` (a buffer, Cube A or Image), sampled
    // with `sampler`, from the next frame on: a program's own input (Session::setChannel). The
    // channel must be unbound or show a picture (an image file or stock texture, which the array
    // replaces); the texture's size and format follow the array. It stays through restarts,
    // resizes and reloads that keep the channel able to take it (dropped otherwise). Errors name
    // the pass and channel; nothing changes on a refused array.
    Status setChannelArray(PassId pass, int channel, const PixelArray& pixels, const SamplerDesc& sampler);
    // The state the next frame starts from (reads every buffer back: not for every frame).
    PlayerState saveState() const;
    // Continues from `state`: canvas size and buffers must match this shadertoy (errors say which
    // does not); nothing changes on failure.
    Status restoreState(const PlayerState& state);
    // Advances one frame without rendering anything: inputs are applied and end their frame, the
    // counters advance. Only for shadertoys without buffers (nothing carries over between their
    // frames), to start a run at a later frame.
    void skipFrame(std::span<const InputEvent> events = {});

    // A tiled still (desc.canvasWidth/Height): draws the last frame's Image again as the tile whose
    // lower-left corner is at `origin` of the canvas (Renderer::drawImageAt).
    void drawImageAt(glm::ivec2 origin) { renderer_->drawImageAt(glm::vec2(origin)); }

    // Where a pass's latest output is (readback, presenting).
    PassOutput output(PassId pass) const { return renderer_->output(pass); }
    // Readbacks and finish() may wait for the GPU: the renderer tells the context's watchdog
    // which pass it waits for (gl/GpuActivity.h).
    void readRgba32f(PassId pass, std::vector<float>& out) const { renderer_->readRgba32f(pass, out); }
    void readRgba8(PassId pass, std::vector<std::uint8_t>& out) const { renderer_->readRgba8(pass, out); }
    // Passes that compiled only after browser-style preprocessing (notices to print).
    const std::vector<Diagnostic>& compileNotices() const { return renderer_->compileNotices(); }
    // Cube A's latest faces (see Renderer::readCubeFace); hasCube() says whether there is one.
    bool hasCube() const { return renderer_->hasCube(); }
    void readCubeFace(int face, std::vector<float>& out, int& size) const { renderer_->readCubeFace(face, out, size); }
    // Waits for the GPU (glFinish); never needed per frame.
    void finish() { renderer_->finish(); }
    // Submits the frame drawn without waiting for it (Renderer::submit).
    void submit() { renderer_->submit(); }

    int width() const { return renderer_->width(); }
    int height() const { return renderer_->height(); }
    const ManifestDesc& manifest() const { return plan_.manifest; }
    const PlayerPlan& plan() const { return plan_; }
    const std::vector<Diagnostic>& notices() const { return plan_.notices; }
    const MouseState& mouse() const { return mouse_; }
    const KeyboardState& keyboard() const { return keyboard_; }
    GlContext& context() { return *context_; }
    // For objects that hold GL resources of this context (a recorder's readback buffers): owning
    // a share keeps the context alive until they are gone.
    std::shared_ptr<GlContext> sharedContext() const { return context_; }

private:
    Player() = default;
    // Per pass (graph order), the code its running program was built from.
    struct BuiltFrom {
        std::string code;
        std::string common;
    };

    std::shared_ptr<GlContext> context_;  // declared first: destroyed after every GL object below
    PlayerDesc desc_;
    PlayerPlan plan_;
    ArrayTextures arrays_;  // setChannelArray's textures, bound again when the renderer is rebuilt
    std::unique_ptr<Renderer> renderer_;
    std::vector<BuiltFrom> built_;
    FrameSequence sequence_;
    MouseState mouse_;
    KeyboardState keyboard_;
    std::uint64_t uploadedKeyboard_ = 0;
    std::vector<SamplePoint> samples_;  // desc_.sampling's pattern (one point: the site's draw)
    std::vector<ImageDraw> draws_;      // this frame's, kept to allocate nothing per frame
};

}  // namespace toyhost
