#include "player/Player.h"

#include <algorithm>
#include <string>

#include "core/Defaults.h"

namespace toyhost {

namespace {

// The canvas must fit GL's own limit as well as toyhost's; checked before any allocation.
Status checkSizeForGl(int width, int height) {
    if (Status size = checkCanvasSize(width, height); !size) return size;
    const int limit = maxTextureSize();
    if (width > limit || height > limit)
        return Error("canvas size " + std::to_string(width) + "x" + std::to_string(height) +
                         " is larger than this GL allows (GL_MAX_TEXTURE_SIZE " + std::to_string(limit) + ")",
                     Code::GlTextureSize);
    return okStatus();
}

RendererDesc rendererDesc(GlContext& context, const PlayerDesc& desc, int width, int height) {
    RendererDesc r;
    r.gpu = &context.gpuActivity();
    r.width = width;
    r.height = height;
    r.floatImageTarget = desc.floatImage;
    r.accumulate = !isSingleSample(desc.sampling);
    r.average.linear = desc.sampling.linear;
    r.average.dither = desc.sampling.dither;
    r.resolutionWidth = desc.canvasWidth;
    r.resolutionHeight = desc.canvasHeight;
    r.allocate = desc.allocate;
    return r;
}

// The images every channel shows, by pass and channel, for telling whether a reload changes them.
std::vector<std::string> channelSources(const ManifestDesc& manifest) {
    std::vector<std::string> keys;
    for (const PassDesc& pass : manifest.passes)
        for (const ChannelDesc& channel : pass.channels)
            keys.push_back(isMediaSource(channelSource(channel.kind)) ? channelImageKey(channel) : std::string());
    return keys;
}

bool samePixels(const Image8& a, const Image8& b) {
    return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

// Whether every picture channel of `a` shows the same pixels in `b` (same bindings assumed): a
// file edited in place has the same path but new content, which must be uploaded again.
bool samePictures(const PlayerPlan& a, const PlayerPlan& b) {
    for (std::size_t p = 0; p < a.manifest.passes.size(); ++p)
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& ca = a.manifest.passes[p].channels[c];
            const ChannelDesc& cb = b.manifest.passes[p].channels[c];
            if (const Image8* x = a.images.find(ca)) {
                const Image8* y = b.images.find(cb);
                if (!y || !samePixels(*x, *y)) return false;
            } else if (const CubeFaces8* x = a.images.findCubemap(ca)) {
                const CubeFaces8* y = b.images.findCubemap(cb);
                if (!y || x->size != y->size) return false;
                for (int f = 0; f < 6; ++f)
                    if (!samePixels(x->faces[f], y->faces[f])) return false;
            } else if (const Volume8* x = a.images.findVolume(ca)) {
                const Volume8* y = b.images.findVolume(cb);
                if (!y || x->width != y->width || x->height != y->height || x->depth != y->depth ||
                    x->channels != y->channels || x->floats != y->floats || x->voxels != y->voxels)
                    return false;
            }
        }
    return true;
}

}  // namespace

Result<std::unique_ptr<Player>> Player::create(std::shared_ptr<GlContext> context, PlayerPlan plan, PlayerDesc desc) {
    if (!context) return Error("the player needs a GL context", Code::Internal);
    if (Status current = context->makeCurrent(); !current) return current.error();
    desc = withDefaults(std::move(desc));
    if (Status size = checkSizeForGl(desc.width, desc.height); !size) return size.error();
    std::unique_ptr<Player> player(new Player());
    player->context_ = std::move(context);
    player->desc_ = desc;
    player->samples_ = samplePattern(desc.sampling);
    player->plan_ = std::move(plan);
    Result<std::unique_ptr<Renderer>> renderer = Renderer::create(
        player->plan_.manifest, player->plan_.graph, rendererDesc(*player->context_, desc, desc.width, desc.height), player->plan_.images,
        player->plan_.sources);
    if (!renderer) return renderer.error();
    player->renderer_ = std::move(*renderer);
    for (const PassDesc& pass : player->plan_.manifest.passes)
        player->built_.push_back({pass.code, player->plan_.manifest.commonCode});
    return player;
}

Player::~Player() {
    // The GL objects below belong to this context; make sure it is the current one while they go.
    if (context_) (void)context_->makeCurrent();
    renderer_.reset();
}

void Player::step(const FrameTime& time, std::span<const InputEvent> events, bool renderImage) {
    for (const InputEvent& event : events) applyInput(event, mouse_, keyboard_);
    if (keyboard_.revision() != uploadedKeyboard_) {
        renderer_->updateKeyboard(keyboard_.texels());
        uploadedKeyboard_ = keyboard_.revision();
    }
    FrameUniforms uniforms;
    uniforms.frame = sequence_.frame();
    uniforms.time = time.time;
    uniforms.timeDelta = static_cast<float>(time.timeDelta);
    uniforms.frameRate = static_cast<float>(time.frameRate);
    uniforms.mouse = mouse_.uniform();
    uniforms.date = time.date;
    draws_.clear();
    if (samples_.size() > 1)  // also for a frame whose Image is drawn later, tile by tile
        for (const SamplePoint& sample : samples_) {
            const FrameTime at = subFrameTime(time, sample.fraction);
            draws_.push_back({sample.offset, at.time, at.date});
        }
    renderer_->renderFrame(uniforms, sequence_.step(), renderImage, draws_);
    mouse_.endFrame();
    keyboard_.endFrame();  // its change is uploaded before the next frame renders
    sequence_.advance();
}

bool Player::repaint(const FrameTime& time) {
    if (sequence_.frame() == 0) return false;
    sequence_.repeat();
    step(time);
    return true;
}

PlayerState Player::saveState() const {
    PlayerState state;
    state.frame = sequence_.frame();
    state.step = sequence_.step();
    state.width = renderer_->width();
    state.height = renderer_->height();
    state.mouse = mouse_.save();
    std::copy(keyboard_.texels().begin(), keyboard_.texels().end(), state.keyboard.begin());
    for (int b = 0; b < kBufferCount; ++b) {
        if (!renderer_->hasBuffer(b)) continue;
        PlayerState::Buffer buffer;
        buffer.index = b;
        for (int slot = 0; slot < 2; ++slot) renderer_->readBufferSlot(b, slot, buffer.slots[slot]);
        state.buffers.push_back(std::move(buffer));
    }
    if (renderer_->hasCube())
        for (int slot = 0; slot < 2; ++slot) renderer_->readCubeSlot(slot, state.cube[slot], state.cubeSize);
    return state;
}

Status Player::restoreState(const PlayerState& state) {
    if (state.width != renderer_->width() || state.height != renderer_->height())
        return Error("the state is for a " + std::to_string(state.width) + "x" + std::to_string(state.height) +
                         " canvas, this one is " + std::to_string(renderer_->width()) + "x" +
                         std::to_string(renderer_->height()),
                     Code::StateSize);
    std::array<bool, kBufferCount> saved{};
    const std::size_t values = static_cast<std::size_t>(state.width) * state.height * 4;
    for (const PlayerState::Buffer& buffer : state.buffers) {
        if (buffer.index < 0 || buffer.index >= kBufferCount || !renderer_->hasBuffer(buffer.index))
            return Error(std::string("the state holds ") + passName(bufferPass(std::clamp(buffer.index, 0, 3))) +
                             ", which this shadertoy does not render",
                         Code::StateBuffers);
        for (const std::vector<float>& slot : buffer.slots)
            if (slot.size() != values) return Error("a buffer of the state has the wrong size", Code::StateBuffers);
        saved[buffer.index] = true;
    }
    for (int b = 0; b < kBufferCount; ++b)
        if (renderer_->hasBuffer(b) && !saved[b])
            return Error(std::string("the state has no ") + passName(bufferPass(b)) + ", which this shadertoy renders",
                         Code::StateBuffers);
    if (renderer_->hasCube() != (state.cubeSize > 0))
        return Error(renderer_->hasCube() ? "the state has no Cube A, which this shadertoy renders"
                                          : "the state holds Cube A, which this shadertoy does not render",
                     Code::StateBuffers);
    if (state.cubeSize > 0) {
        const std::size_t cubeValues = std::size_t(6) * state.cubeSize * state.cubeSize * 4;
        if (state.cubeSize != defaults::kCubeBufferSize || state.cube[0].size() != cubeValues ||
            state.cube[1].size() != cubeValues)
            return Error("Cube A of the state has the wrong size", Code::StateBuffers);
    }
    for (const PlayerState::Buffer& buffer : state.buffers)
        for (int slot = 0; slot < 2; ++slot) renderer_->writeBufferSlot(buffer.index, slot, buffer.slots[slot]);
    if (state.cubeSize > 0)
        for (int slot = 0; slot < 2; ++slot) renderer_->writeCubeSlot(slot, state.cube[slot]);
    sequence_.restore(state.frame, state.step);
    mouse_.restore(state.mouse);
    keyboard_.restore(state.keyboard);
    return okStatus();
}

void Player::skipFrame(std::span<const InputEvent> events) {
    for (const InputEvent& event : events) applyInput(event, mouse_, keyboard_);
    mouse_.endFrame();
    keyboard_.endFrame();
    sequence_.advance();
}

Status Player::resize(int width, int height) {
    if (width == renderer_->width() && height == renderer_->height()) return okStatus();
    if (Status size = checkSizeForGl(width, height); !size) return size;
    return renderer_->resize(width, height);
}

void Player::restart() {
    sequence_.restart();
    renderer_->clearBuffers();
}

namespace {

// Why channel `channel` of `pass` cannot show an array; empty when it can.
std::string arrayRefusal(const ManifestDesc& manifest, PassId pass, int channel) {
    const PassDesc* desc = manifest.find(pass);
    if (!desc) return "the shadertoy has no such pass";
    const ChannelDesc& bound = desc->channels[channel];
    if (bound.samplerType != SamplerType::Sampler2D)
        return std::string("it is declared as a ") + (bound.samplerType == SamplerType::SamplerCube ? "samplerCube" : "sampler3D") +
               " (an array is a 2D texture)";
    if (bound.kind != ChannelKind::None && bound.kind != ChannelKind::ImageFile && bound.kind != ChannelKind::StockMedia)
        return std::string("it is bound to a ") + channelKindName(bound.kind) +
               " (an array takes an unbound channel or one showing a picture)";
    return "";
}

}  // namespace

Status Player::setChannelArray(PassId pass, int channel, const PixelArray& pixels, const SamplerDesc& sampler) {
    const std::string where = std::string(passName(pass)) + " iChannel" + std::to_string(channel);
    if (channel < 0 || channel >= kChannelCount)
        return Error(std::string(passName(pass)) + ": no channel " + std::to_string(channel) + " (0..3)", Code::Usage);
    if (pass == PassId::Sound)
        return Error(where + ": the Sound pass is rendered before any frame; an array is shown from the next frame",
                     Code::Usage);
    if (std::string refusal = arrayRefusal(plan_.manifest, pass, channel); !refusal.empty())
        return Error(where + ": cannot show an array: " + refusal, Code::Usage);
    if (Status shape = checkPixelArray(pixels, maxTextureSize(), where); !shape) return shape;
    if (sampler.filter == Filter::Mipmap && pixels.type != PixelType::UInt8)
        return Error(where + ": mipmap filtering takes uint8 arrays (GLES 3 cannot make mipmaps of float textures "
                             "everywhere); sample a float32 array nearest or linear",
                     Code::Usage);
    Result<const ArrayTextures::Entry*> entry = arrays_.upload({pass, channel}, pixels, sampler);
    if (!entry) return inPass(passName(pass), entry.error());
    renderer_->bindPicture(pass, channel, (*entry)->texture.id(), (*entry)->width, (*entry)->height, sampler);
    return okStatus();
}

ReloadReport Player::reload(PlayerPlan next) {
    ReloadReport report;
    const bool sameStructure = plan_.graph.sameStructure(next.graph) &&
                               channelSources(plan_.manifest) == channelSources(next.manifest) &&
                               samePictures(plan_, next);
    if (!sameStructure) {
        report.structureChanged = true;
        Result<std::unique_ptr<Renderer>> renderer = Renderer::create(
            next.manifest, next.graph, rendererDesc(*context_, desc_, renderer_->width(), renderer_->height()), next.images,
            next.sources);
        if (!renderer) {
            report.problems = renderer.error().diagnostics;
            return report;
        }
        (*renderer)->takeBuffersFrom(*renderer_);
        renderer_ = std::move(*renderer);
        plan_ = std::move(next);
        // The program's arrays stay where the new structure still lets a channel show one.
        std::vector<ArrayTextures::Key> dropped;
        for (const auto& [key, entry] : arrays_.entries()) {
            if (arrayRefusal(plan_.manifest, key.first, key.second).empty())
                renderer_->bindPicture(key.first, key.second, entry.texture.id(), entry.width, entry.height,
                                       entry.sampler);
            else
                dropped.push_back(key);
        }
        for (const ArrayTextures::Key& key : dropped) arrays_.erase(key);
        built_.clear();
        for (const PassDesc& pass : plan_.manifest.passes) {
            built_.push_back({pass.code, plan_.manifest.commonCode});
            report.recompiled.push_back(passName(pass.id));
        }
        // The new renderer's keyboard texture starts empty: upload the state before the next frame.
        uploadedKeyboard_ = keyboard_.revision() + 1;
        report.applied = true;
        return report;
    }
    // Same passes and bindings: recompile only the passes whose code (or Common) changed. A pass
    // that fails keeps running what it ran; its record stays, so the next change retries it.
    for (std::size_t i = 0; i < next.manifest.passes.size(); ++i) {
        const PassDesc& pass = next.manifest.passes[i];
        if (pass.code == built_[i].code && next.manifest.commonCode == built_[i].common) continue;
        Status replaced = renderer_->replaceProgram(i, next.manifest, pass, next.sources.at(i));
        if (!replaced) {
            report.problems.insert(report.problems.end(), replaced.error().diagnostics.begin(),
                                   replaced.error().diagnostics.end());
            continue;
        }
        built_[i] = {pass.code, next.manifest.commonCode};
        report.recompiled.push_back(passName(pass.id));
    }
    report.applied = !report.recompiled.empty();
    // The plan now describes what runs, except for the code of passes that failed (kept in built_).
    plan_ = std::move(next);
    return report;
}

}  // namespace toyhost
