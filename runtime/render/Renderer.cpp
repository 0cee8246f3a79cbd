#include "render/Renderer.h"

#include "shader/CompilerLog.h"

#include <algorithm>

#include <GLES3/gl3.h>
#include <map>
#include <string>
#include <tuple>

#include "core/Defaults.h"
#include "gl/GlContext.h"
#include "gl/GlObjects.h"
#include "image/PixelConversion.h"
#include "render/ChannelBindings.h"
#include "render/CubeTarget.h"
#include "render/PassProgram.h"
#include "render/SampleAccumulator.h"
#include "shader/ImageCoverage.h"

namespace toyhost {

namespace {

struct PassRuntime {
    PassPlan plan;
    PassProgram program;
    PassBindings bindings;
};

}  // namespace

struct Renderer::Impl {
    TextureAllocator allocate;
    GlVertexArray vertexArray = makeVertexArray();
    InputTextures inputs;  // every texture a channel binds but buffers, and the samplers
    std::array<std::optional<PingPongTarget>, kBufferCount> buffers;
    std::optional<CubeTarget> cube;  // Cube A
    RenderTexture imageTarget;
    bool floatImage = false;
    std::optional<SampleAccumulator> accumulator;  // when frames average several Image draws
    bool imageMayDiscard = false;  // each draw starts from the canvas (SampleAccumulator::seed)
    glm::vec2 resolution{0.0f};   // iResolution of the canvas passes (the tiled whole, else the target)
    glm::vec2 imageOrigin{0.0f};  // where the Image target sits in the canvas (a tile's corner)
    FrameUniforms lastUniforms;   // the last frame's, for drawing Image again at another origin
    std::vector<ImageDraw> lastDraws;
    std::uint64_t lastStep = 0;
    std::vector<PassRuntime> passes;
    GpuActivity* gpu = nullptr;  // never null once created
    std::vector<Diagnostic> compileNotices;
    // The other type's values for readRgba32f / readRgba8 (a target read as it is, then
    // converted), kept between reads so that a read per frame allocates nothing.
    mutable std::vector<std::uint8_t> readBytes;
    mutable std::vector<float> readFloats;

    // Compiles `pass`, telling the watchdog which pass is compiling.
    Result<PassProgram> compile(const ManifestDesc& manifest, const PassDesc& pass, const PassSource& source) {
        Result<PassProgram> program = [&] {
            GpuActivity::Compiling compiling(*gpu, passName(pass.id));
            return compilePassProgram(manifest, pass, source);
        }();
        if (program && program->browserPreprocessed) {
            Diagnostic notice;
            notice.severity = Severity::Notice;
            notice.code = Code::ShaderPreprocessed;
            notice.pass = passName(pass.id);
            notice.file = pass.sourceName;
            notice.message = "Mesa's GLSL preprocessor refused this pass; it compiled after preprocessing the way "
                             "browsers do";
            compileNotices.push_back(std::move(notice));
        }
        if (program)
            for (const Diagnostic& warning : program->warnings) compileNotices.push_back(warning);
        return program;
    }

    GLenum imageFormat() const { return floatImage ? GL_RGBA32F : GL_RGBA8; }

    // Binds `pass`'s program, its channels' textures for `step` and the frame's uniforms; returns
    // the textures of the channels that change per step (buffers, Cube A), for binding them again.
    std::array<GLuint, kChannelCount> usePass(PassRuntime& pass, const FrameUniforms& u, std::uint64_t step,
                                              glm::vec2 canvas) {
        glUseProgram(pass.program.program.id());
        const UniformLocations& loc = pass.program.uniforms;
        glUniform3f(loc.resolution, canvas.x, canvas.y, 1.0f);
        glUniform1f(loc.time, static_cast<float>(u.time));  // narrowed here only (FrameUniforms::time)
        glUniform1f(loc.timeDelta, u.timeDelta);
        glUniform1f(loc.frameRate, u.frameRate);
        glUniform1i(loc.frame, u.frame);
        glUniform4f(loc.mouse, u.mouse.x, u.mouse.y, u.mouse.z, u.mouse.w);
        glUniform4f(loc.date, u.date.x, u.date.y, u.date.z, u.date.w);
        setTimedUniforms(loc, pass.bindings);
        std::array<GLuint, kChannelCount> dynamic{};
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelPlan& plan = pass.plan.channels[c];
            if (plan.kind == ChannelKind::Buffer)
                dynamic[c] = buffers[plan.buffer]->slot(slotRead(plan.age, step)).texture.id();
            else if (plan.kind == ChannelKind::CubeBuffer)
                dynamic[c] = cube->texture(slotRead(plan.age, step));
        }
        bindTextures(pass.bindings, dynamic);
        return dynamic;
    }

    // The Image pass into the Image target: one draw at imageOrigin, or each of `draws` (their
    // offsets from imageOrigin, their iTime and iDate) into the accumulator's float target, added
    // up and averaged. Each of several draws is its own for the watchdog (GpuActivity::beforeSample).
    void drawImage(PassRuntime& pass, const FrameUniforms& u, std::uint64_t step, std::span<const ImageDraw> draws) {
        const UniformLocations& loc = pass.program.uniforms;
        const char* name = passName(pass.plan.id);
        if (draws.size() <= 1 || !accumulator) {
            glBindFramebuffer(GL_FRAMEBUFFER, imageTarget.framebuffer.id());
            usePass(pass, u, step, resolution);
            glUniform2f(loc.fragOffset, imageOrigin.x, imageOrigin.y);
            gpu->beforeDraw(name, u.frame);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            gpu->afterDraw(name, u.frame);
            return;
        }
        std::array<GLuint, kChannelCount> dynamic{};
        int count = 0;  // the draws added (a watchdog's expiry stops them: its error follows)
        for (const ImageDraw& draw : draws) {
            if (gpu->cancelled()) break;
            const int d = count++;
            gpu->beforeSample(name, u.frame, d, static_cast<int>(draws.size()));
            if (imageMayDiscard) accumulator->seed(imageTarget.texture.id());
            glBindFramebuffer(GL_FRAMEBUFFER, accumulator->sampleFramebuffer());
            if (d == 0) {
                dynamic = usePass(pass, u, step, resolution);
            } else {  // back from the accumulator's program and texture units
                glUseProgram(pass.program.program.id());
                bindTextures(pass.bindings, dynamic);
            }
            glUniform1f(loc.time, static_cast<float>(draw.time));
            glUniform4f(loc.date, draw.date.x, draw.date.y, draw.date.z, draw.date.w);
            glUniform2f(loc.fragOffset, imageOrigin.x + draw.offset.x, imageOrigin.y + draw.offset.y);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            accumulator->add(d == 0);
            gpu->afterSample();
        }
        if (count == 0) return;
        gpu->beforeDraw(name, u.frame);
        accumulator->resolve(imageTarget.framebuffer.id(), count);
        gpu->afterDraw(name, u.frame);
    }

    // The uniforms that change only when the program, the bindings or the canvas change.
    void setStaticUniforms(PassRuntime& pass) const {
        glUseProgram(pass.program.program.id());
        setChannelUniforms(pass.program.uniforms, pass.bindings);
        glUseProgram(0);
    }
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() {
    // Its draws' fences go with it (the context is current while a renderer lives).
    if (impl_) impl_->gpu->clear();
}

Result<std::unique_ptr<Renderer>> Renderer::create(const ManifestDesc& manifest, const PassGraph& graph,
                                                   const RendererDesc& desc, const ChannelMedia& images,
                                                   std::span<const PassSource> sources) {
    if (Status features = checkRequiredGlFeatures(); !features) return features.error();
    auto impl = std::make_unique<Impl>();
    impl->allocate = desc.allocate ? desc.allocate : TextureAllocator(createRenderTexture);
    if (!desc.gpu) return Error("Renderer::create: no GpuActivity (the context's gpuActivity())", Code::Internal);
    if (sources.size() != manifest.passes.size())
        return Error("Renderer::create: " + std::to_string(sources.size()) + " prepared sources for " +
                         std::to_string(manifest.passes.size()) + " passes (planPlayer prepares them)",
                     Code::Internal);
    impl->gpu = desc.gpu;
    const int w = desc.width, h = desc.height;
    impl->resolution = desc.resolutionWidth > 0 ? glm::vec2(desc.resolutionWidth, desc.resolutionHeight) : glm::vec2(w, h);
    const std::array<float, 3> canvas{impl->resolution.x, impl->resolution.y, 1.0f};

    // Every program first: a shader error is reported before any large allocation, and all
    // failing passes are reported together.
    std::vector<Diagnostic> problems;
    std::vector<PassProgram> programs;
    for (size_t p = 0; p < graph.passes.size(); ++p) {
        Result<PassProgram> program = impl->compile(manifest, manifest.passes[p], sources[p]);
        if (!program) {
            mergeCompileProblems(problems, program.error().diagnostics, manifest);
            continue;
        }
        programs.push_back(std::move(*program));
    }
    if (!problems.empty()) return Error(std::move(problems));

    for (int b = 0; b < kBufferCount; ++b) {
        if (!graph.bufferUsed[b]) continue;
        Result<PingPongTarget> target = PingPongTarget::create(w, h, graph.bufferMipmapped[b], impl->allocate);
        if (!target) return inPass(passName(bufferPass(b)), target.error());
        impl->buffers[b] = std::move(*target);
    }
    if (graph.cubeUsed) {
        Result<CubeTarget> cube = CubeTarget::create(defaults::kCubeBufferSize, graph.cubeMipmapped);
        if (!cube) return inPass("Cube A", cube.error());
        impl->cube = std::move(*cube);
    }
    impl->floatImage = desc.floatImageTarget;
    Result<RenderTexture> image = impl->allocate(w, h, impl->imageFormat(), false);
    if (!image) return inPass("Image", image.error());
    impl->imageTarget = std::move(*image);
    if (desc.accumulate) {
        SampleAverage average = desc.average;
        average.floatTarget = desc.floatImageTarget;
        Result<SampleAccumulator> accumulator = SampleAccumulator::create(w, h, average, impl->allocate);
        if (!accumulator) return inPass("Image", accumulator.error());
        impl->accumulator = std::move(*accumulator);
        impl->imageMayDiscard = imageMayKeepPixels(manifest);
    }

    BindOptions bind;
    bind.canvas = canvas;
    for (size_t p = 0; p < graph.passes.size(); ++p) {
        const PassPlan& plan = graph.passes[p];
        std::array<SamplerDesc, kChannelCount> samplers;
        for (int c = 0; c < kChannelCount; ++c) samplers[c] = plan.channels[c].sampler;
        Result<PassBindings> bindings = bindChannels(manifest.passes[p], samplers, images, impl->inputs, bind);
        if (!bindings) return bindings.error();
        PassRuntime pass{plan, std::move(programs[p]), std::move(*bindings)};
        impl->setStaticUniforms(pass);
        impl->passes.push_back(std::move(pass));
    }
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: setting up the passes failed: ") + glErrorName(error), Code::GlSetup);

    std::unique_ptr<Renderer> renderer(new Renderer(std::move(impl)));
    renderer->width_ = w;
    renderer->height_ = h;
    return renderer;
}

void Renderer::renderFrame(const FrameUniforms& u, std::uint64_t step, bool renderImage,
                           std::span<const ImageDraw> draws) {
    Impl& s = *impl_;
    // Videos and audio to this frame's time, before any pass reads them. A decoder that fails
    // mid-run (a file truncated on disk) keeps its last frame; the failure was the file's.
    if (s.inputs.updateTimed(u.time, u.frame, s.gpu->activity())) s.gpu->forgetPublished();
    glBindVertexArray(s.vertexArray.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    s.lastUniforms = u;
    s.lastDraws.assign(draws.begin(), draws.end());
    for (PassRuntime& pass : s.passes) {
        const bool isCube = pass.plan.targetCube;
        const bool isImage = pass.plan.targetBuffer < 0 && !isCube;
        if (isImage && !renderImage) continue;
        // A driver may block here while earlier passes draw: say which one.
        s.gpu->publishPending();
        if (isImage) {
            s.drawImage(pass, u, step, draws);
            continue;
        }
        if (!isCube) glBindFramebuffer(GL_FRAMEBUFFER, s.buffers[pass.plan.targetBuffer]->slot(slotWritten(step)).framebuffer.id());
        const UniformLocations& loc = pass.program.uniforms;
        s.usePass(pass, u, step, isCube ? glm::vec2(s.cube->size()) : s.resolution);
        s.gpu->beforeDraw(passName(pass.plan.id), u.frame);
        if (isCube) {
            // The six faces, each with its viewport and corner directions (site: Paint_Cubemap).
            const int size = s.cube->size();
            glViewport(0, 0, size, size);
            glUniform4f(loc.viewport, 0.0f, 0.0f, float(size), float(size));
            for (int face = 0; face < 6; ++face) {
                glBindFramebuffer(GL_FRAMEBUFFER, s.cube->faceFramebuffer(slotWritten(step), face));
                float corners[15] = {};
                std::copy(cubeFaceCorners()[face].begin(), cubeFaceCorners()[face].end(), corners);
                glUniform3fv(loc.corners, 5, corners);
                glDrawArrays(GL_TRIANGLES, 0, 3);
            }
            glViewport(0, 0, width_, height_);
            s.cube->generateMipmaps(slotWritten(step));
        } else {
            glDrawArrays(GL_TRIANGLES, 0, 3);
            // Mipmaps of a buffer are regenerated only when some channel samples it with `mipmap`.
            s.buffers[pass.plan.targetBuffer]->generateMipmaps(slotWritten(step));
        }
        s.gpu->afterDraw(passName(pass.plan.id), u.frame);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    s.lastStep = step;
}

void Renderer::drawImageAt(glm::vec2 origin) {
    Impl& s = *impl_;
    s.imageOrigin = origin;
    glBindVertexArray(s.vertexArray.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    for (PassRuntime& pass : s.passes)
        if (pass.plan.targetBuffer < 0 && !pass.plan.targetCube) {
            s.gpu->publishPending();
            s.drawImage(pass, s.lastUniforms, s.lastStep, s.lastDraws);
        }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool Renderer::hasBuffer(int index) const { return impl_->buffers[index].has_value(); }

void Renderer::readBufferSlot(int index, int slot, std::vector<float>& out) const {
    const RenderTexture& target = impl_->buffers[index]->slot(slot);
    GpuActivity::Wait wait(impl_->gpu);
    out.resize(static_cast<std::size_t>(width_) * height_ * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Renderer::writeBufferSlot(int index, int slot, std::span<const float> rgba) {
    const PingPongTarget& buffer = *impl_->buffers[index];
    glBindTexture(GL_TEXTURE_2D, buffer.slot(slot).texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_FLOAT, rgba.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    buffer.generateMipmaps(slot);
}

void Renderer::updateKeyboard(std::span<const std::uint8_t> texels) { impl_->inputs.updateKeyboard(texels); }

Status Renderer::resize(int width, int height) {
    Impl& s = *impl_;
    // Allocate everything first; any failure returns before the current state is touched.
    std::array<std::optional<PingPongTarget>, kBufferCount> buffers;
    for (int b = 0; b < kBufferCount; ++b) {
        if (!s.buffers[b]) continue;
        Result<PingPongTarget> target = PingPongTarget::create(width, height, s.buffers[b]->mipmapped(), s.allocate);
        if (!target) return inPass(passName(bufferPass(b)), target.error());
        buffers[b] = std::move(*target);
    }
    Result<RenderTexture> image = s.allocate(width, height, s.imageFormat(), false);
    if (!image) return inPass("Image", image.error());
    if (s.accumulator)
        if (Status sums = s.accumulator->resize(width, height, s.allocate); !sums) return inPass("Image", sums.error());

    for (int b = 0; b < kBufferCount; ++b)
        if (buffers[b]) {
            buffers[b]->copyContentFrom(*s.buffers[b]);
            s.buffers[b] = std::move(buffers[b]);
        }
    s.imageTarget = std::move(*image);
    width_ = width;
    height_ = height;
    s.resolution = glm::vec2(width, height);
    for (PassRuntime& pass : s.passes) {
        for (ChannelBinding& channel : pass.bindings.channels)
            if (channel.source == ChannelSource::Buffer) channel.resolution = {float(width), float(height), 1};
        s.setStaticUniforms(pass);
    }
    return okStatus();
}

void Renderer::bindPicture(PassId id, int channel, GLuint texture, int width, int height, const SamplerDesc& sampler) {
    for (PassRuntime& pass : impl_->passes) {
        if (pass.plan.id != id) continue;
        ChannelBinding& binding = pass.bindings.channels[channel];
        binding.source = ChannelSource::Picture;
        binding.target = GL_TEXTURE_2D;
        binding.texture = texture;
        binding.sampler = impl_->inputs.sampler(sampler);
        binding.resolution = {float(width), float(height), 1.0f};
        binding.timed = nullptr;
        impl_->setStaticUniforms(pass);
    }
}

void Renderer::clearBuffers() {
    for (auto& buffer : impl_->buffers)
        if (buffer) buffer->clear();
    if (impl_->cube) impl_->cube->clear();
}

Status Renderer::replaceProgram(std::size_t index, const ManifestDesc& manifest, const PassDesc& pass,
                                const PassSource& source) {
    Result<PassProgram> program = impl_->compile(manifest, pass, source);
    if (!program) return program.error();
    PassRuntime& runtime = impl_->passes.at(index);
    runtime.program = std::move(*program);
    impl_->setStaticUniforms(runtime);
    return okStatus();
}

void Renderer::takeBuffersFrom(Renderer& old) {
    for (int b = 0; b < kBufferCount; ++b) {
        std::optional<PingPongTarget>& mine = impl_->buffers[b];
        std::optional<PingPongTarget>& theirs = old.impl_->buffers[b];
        if (!mine || !theirs) continue;
        if (theirs->width() == mine->width() && theirs->height() == mine->height() &&
            theirs->mipmapped() == mine->mipmapped())
            mine = std::move(theirs);
        else
            mine->copyContentFrom(*theirs);
    }
    if (impl_->cube && old.impl_->cube && impl_->cube->mipmapped() == old.impl_->cube->mipmapped())
        impl_->cube = std::move(old.impl_->cube);
    impl_->lastStep = old.impl_->lastStep;
}

void Renderer::finish() {
    GpuActivity::Wait wait(impl_->gpu);
    glFinish();
}

void Renderer::submit() { glFlush(); }

const std::vector<Diagnostic>& Renderer::compileNotices() const { return impl_->compileNotices; }

PassOutput Renderer::output(PassId pass) const {
    if (pass == PassId::Image)
        return {impl_->imageTarget.framebuffer.id(), impl_->imageTarget.texture.id(), width_, height_,
                impl_->floatImage ? PixelFormat::Rgba32f : PixelFormat::Rgba8};
    if (!isBuffer(pass)) return {};  // Cube A's faces are read with readCubeFaces
    const auto& buffer = impl_->buffers[bufferIndex(pass)];
    if (!buffer) return {};
    const RenderTexture& slot = buffer->slot(slotWritten(impl_->lastStep));
    return {slot.framebuffer.id(), slot.texture.id(), width_, height_, PixelFormat::Rgba32f};
}

void Renderer::readRgba32f(PassId pass, std::vector<float>& out) const {
    const PassOutput source = output(pass);
    GpuActivity::Wait wait(impl_->gpu);
    out.resize(static_cast<size_t>(width_) * height_ * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (source.format == PixelFormat::Rgba8) {
        std::vector<std::uint8_t>& bytes = impl_->readBytes;
        bytes.resize(out.size());
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        for (size_t i = 0; i < bytes.size(); ++i) out[i] = bytes[i] / 255.0f;
    } else {
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

bool Renderer::hasCube() const { return impl_->cube.has_value(); }

void Renderer::readCubeFace(int face, std::vector<float>& out, int& size) const {
    const CubeTarget& cube = *impl_->cube;
    GpuActivity::Wait wait(impl_->gpu);
    size = cube.size();
    out.resize(static_cast<std::size_t>(size) * size * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, cube.faceFramebuffer(slotWritten(impl_->lastStep), face));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, out.data());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Renderer::readCubeSlot(int slot, std::vector<float>& out, int& size) const {
    const CubeTarget& cube = *impl_->cube;
    GpuActivity::Wait wait(impl_->gpu);
    size = cube.size();
    const std::size_t face = static_cast<std::size_t>(size) * size * 4;
    out.resize(6 * face);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, cube.faceFramebuffer(slot, f));
        glReadPixels(0, 0, size, size, GL_RGBA, GL_FLOAT, out.data() + f * face);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Renderer::writeCubeSlot(int slot, std::span<const float> faces) {
    const CubeTarget& cube = *impl_->cube;
    const int size = cube.size();
    const std::size_t face = static_cast<std::size_t>(size) * size * 4;
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube.texture(slot));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; ++f)
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, 0, 0, size, size, GL_RGBA, GL_FLOAT,
                        faces.data() + f * face);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    cube.generateMipmaps(slot);
}

void Renderer::readRgba8(PassId pass, std::vector<std::uint8_t>& out) const {
    const PassOutput source = output(pass);
    GpuActivity::Wait wait(impl_->gpu);
    out.resize(static_cast<size_t>(width_) * height_ * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source.framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (source.format == PixelFormat::Rgba32f) {
        // Convert as GL does when writing float colour to a UNORM8 target.
        std::vector<float>& floats = impl_->readFloats;
        floats.resize(out.size());
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, floats.data());
        toUnorm8(floats, out);
    } else {
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace toyhost
