#include "render/Renderer.h"

#include <GLES3/gl3.h>
#include <optional>
#include <string>

#include "capture/PixelConversion.h"
#include "gl/GlContext.h"
#include "gl/GlObjects.h"
#include "gl/ShaderProgram.h"
#include "render/ChannelTextures.h"
#include "render/PingPongTarget.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

namespace {

// Uniform locations, looked up once after linking; -1 where the shader does not use one.
struct UniformLocations {
    GLint resolution = -1, time = -1, timeDelta = -1, frameRate = -1, frame = -1, mouse = -1, date = -1,
          sampleRate = -1, channelTime = -1, channelResolution = -1;
    std::array<GLint, kChannelCount> chSize{-1, -1, -1, -1}, chTime{-1, -1, -1, -1}, chLoaded{-1, -1, -1, -1};

    UniformLocations() = default;
    explicit UniformLocations(GLuint program) {
        auto at = [&](const std::string& name) { return glGetUniformLocation(program, name.c_str()); };
        resolution = at("iResolution");
        time = at("iTime");
        timeDelta = at("iTimeDelta");
        frameRate = at("iFrameRate");
        frame = at("iFrame");
        mouse = at("iMouse");
        date = at("iDate");
        sampleRate = at("iSampleRate");
        channelTime = at("iChannelTime");
        channelResolution = at("iChannelResolution");
        for (int i = 0; i < kChannelCount; ++i) {
            const std::string ch = "iCh" + std::to_string(i);
            chSize[i] = at(ch + ".size");
            chTime[i] = at(ch + ".time");
            chLoaded[i] = at(ch + ".loaded");
        }
    }
};

// What a channel binds, fixed after creation except for buffers, whose slot depends on the frame.
struct ChannelBinding {
    GLuint texture = 0;            // non-buffer inputs
    GLuint sampler = 0;
    std::array<float, 3> resolution{0, 0, 0};
};

struct PassRuntime {
    PassPlan plan;
    GlProgram program;
    UniformLocations uniforms;
    std::array<ChannelBinding, kChannelCount> channels;
};

}  // namespace

struct Renderer::Impl {
    SamplerSet samplers;
    GlVertexArray vertexArray = makeVertexArray();
    std::optional<KeyboardTexture> keyboard;
    std::array<std::optional<PingPongTarget>, kBufferCount> buffers;
    RenderTexture imageTarget;
    bool floatImage = false;
    std::vector<InputTexture> inputs;
    std::vector<PassRuntime> passes;
    int lastFrame = -1;
    bool imageRendered = false;

    void setStaticUniforms(PassRuntime& pass) {
        glUseProgram(pass.program.id());
        for (int i = 0; i < kChannelCount; ++i) {
            // Texture unit i carries iChannel i (and iCh i.sampler in the Image pass).
            glUniform1i(glGetUniformLocation(pass.program.id(), ("iChannel" + std::to_string(i)).c_str()), i);
            glUniform1i(glGetUniformLocation(pass.program.id(), ("iCh" + std::to_string(i) + ".sampler").c_str()), i);
            glUniform1i(pass.uniforms.chLoaded[i], pass.plan.channels[i].kind != ChannelKind::None);
            glUniform1f(pass.uniforms.chTime[i], 0.0f);
        }
        glUniform1f(pass.uniforms.sampleRate, 44100.0f);
        const float zeros[4] = {0, 0, 0, 0};
        glUniform1fv(pass.uniforms.channelTime, 4, zeros);  // no video or audio inputs
        setResolutionUniforms(pass);
        glUseProgram(0);
    }

    void setResolutionUniforms(PassRuntime& pass) {
        std::array<float, 3 * kChannelCount> resolutions{};
        for (int i = 0; i < kChannelCount; ++i) {
            for (int k = 0; k < 3; ++k) resolutions[3 * i + k] = pass.channels[i].resolution[k];
            glUniform3fv(pass.uniforms.chSize[i], 1, pass.channels[i].resolution.data());
        }
        glUniform3fv(pass.uniforms.channelResolution, kChannelCount, resolutions.data());
    }
};

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(const ManifestDesc& manifest, const PassGraph& graph,
                                                   const RendererOptions& options,
                                                   const ImageProvider& images) {
    if (Status features = checkRequiredGlFeatures(); !features) return features.error();
    auto impl = std::make_unique<Impl>();
    const int w = options.width, h = options.height;
    const std::array<float, 3> canvas{float(w), float(h), 1.0f};

    for (int b = 0; b < kBufferCount; ++b) {
        if (!graph.bufferUsed[b]) continue;
        Result<PingPongTarget> target = PingPongTarget::create(w, h, graph.bufferMipmapped[b]);
        if (!target) return withContext(passName(bufferPass(b)), target.error());
        impl->buffers[b] = std::move(*target);
    }
    impl->floatImage = options.floatImageTarget;
    Result<RenderTexture> image =
        createRenderTexture(w, h, options.floatImageTarget ? GL_RGBA32F : GL_RGBA8, false);
    if (!image) return withContext("Image", image.error());
    impl->imageTarget = std::move(*image);

    impl->inputs.reserve(graph.passes.size() * kChannelCount);
    for (size_t p = 0; p < graph.passes.size(); ++p) {
        const PassPlan& plan = graph.passes[p];
        const PassDesc& desc = manifest.passes[p];
        ShaderInputs shaderInputs;
        shaderInputs.pass = plan.id;
        shaderInputs.common = manifest.commonSource ? &manifest.commonCode : nullptr;
        shaderInputs.code = desc.code;
        AssembledShader fragment = assembleFragmentShader(shaderInputs);
        ProgramSources names{passName(plan.id), desc.sourceName, manifest.commonName};
        Result<GlProgram> program = buildProgram(fragment, names);
        if (!program) return program.error();

        PassRuntime pass{plan, std::move(*program), {}, {}};
        pass.uniforms = UniformLocations(pass.program.id());
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelPlan& channel = plan.channels[c];
            ChannelBinding& binding = pass.channels[c];
            binding.sampler = impl->samplers.get(channel.sampler);
            const std::string where = std::string(passName(plan.id)) + " / iChannel" + std::to_string(c);
            switch (channel.kind) {
                case ChannelKind::None: binding.sampler = 0; break;
                case ChannelKind::Buffer: binding.resolution = canvas; break;
                case ChannelKind::Keyboard:
                    if (!impl->keyboard) impl->keyboard.emplace();
                    binding.texture = impl->keyboard->id();
                    binding.resolution = {float(KeyboardTexture::kWidth), float(KeyboardTexture::kHeight), 1};
                    break;
                case ChannelKind::ImageFile:
                case ChannelKind::StockMedia: {
                    Result<Image8> pixels = images(desc.channels[c]);
                    if (!pixels) return withContext(where, pixels.error());
                    impl->inputs.push_back(uploadImage(*pixels, channel.sampler));
                    binding.texture = impl->inputs.back().texture.id();
                    binding.resolution = {float(pixels->width), float(pixels->height), 1};
                    break;
                }
            }
        }
        impl->setStaticUniforms(pass);
        impl->passes.push_back(std::move(pass));
    }
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error{std::string("GL: setting up the passes failed: ") + glErrorName(error)};

    std::unique_ptr<Renderer> renderer(new Renderer(std::move(impl)));
    renderer->width_ = w;
    renderer->height_ = h;
    return renderer;
}

void Renderer::renderFrame(const FrameUniforms& u, bool renderImage) {
    Impl& s = *impl_;
    glBindVertexArray(s.vertexArray.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    for (PassRuntime& pass : s.passes) {
        const bool isImage = pass.plan.targetBuffer < 0;
        if (isImage && !renderImage) continue;
        GLuint target = isImage ? s.imageTarget.framebuffer.id()
                                : s.buffers[pass.plan.targetBuffer]->slot(slotWritten(u.frame)).framebuffer.id();
        glBindFramebuffer(GL_FRAMEBUFFER, target);
        glUseProgram(pass.program.id());
        const UniformLocations& loc = pass.uniforms;
        glUniform3f(loc.resolution, float(width_), float(height_), 1.0f);
        glUniform1f(loc.time, u.time);
        glUniform1f(loc.timeDelta, u.timeDelta);
        glUniform1f(loc.frameRate, u.frameRate);
        glUniform1i(loc.frame, u.frame);
        glUniform4f(loc.mouse, u.mouse.x, u.mouse.y, u.mouse.z, u.mouse.w);
        glUniform4f(loc.date, u.date.x, u.date.y, u.date.z, u.date.w);
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelPlan& plan = pass.plan.channels[c];
            GLuint texture = pass.channels[c].texture;
            if (plan.kind == ChannelKind::Buffer)
                texture = s.buffers[plan.buffer]->slot(slotRead(plan.age, u.frame)).texture.id();
            glActiveTexture(GL_TEXTURE0 + c);
            glBindTexture(GL_TEXTURE_2D, texture);
            glBindSampler(c, pass.channels[c].sampler);
        }
        glDrawArrays(GL_TRIANGLES, 0, 3);
        if (!isImage && s.buffers[pass.plan.targetBuffer]->mipmapped()) {
            // Mipmaps of a buffer are regenerated only when some channel samples it with `mipmap`.
            glActiveTexture(GL_TEXTURE0);
            glBindTexture(GL_TEXTURE_2D,
                          s.buffers[pass.plan.targetBuffer]->slot(slotWritten(u.frame)).texture.id());
            glGenerateMipmap(GL_TEXTURE_2D);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    s.lastFrame = u.frame;
    s.imageRendered = renderImage;
}

void Renderer::updateKeyboard(std::span<const std::uint8_t> texels) {
    if (impl_->keyboard) impl_->keyboard->update(texels);
}

Status Renderer::resize(int width, int height) {
    for (auto& buffer : impl_->buffers)
        if (buffer)
            if (Status resized = buffer->resize(width, height); !resized) return resized;
    Result<RenderTexture> image =
        createRenderTexture(width, height, impl_->floatImage ? GL_RGBA32F : GL_RGBA8, false);
    if (!image) return image.error();
    impl_->imageTarget = std::move(*image);
    for (PassRuntime& pass : impl_->passes) {
        for (int c = 0; c < kChannelCount; ++c)
            if (pass.plan.channels[c].kind == ChannelKind::Buffer)
                pass.channels[c].resolution = {float(width), float(height), 1};
        glUseProgram(pass.program.id());
        impl_->setResolutionUniforms(pass);
    }
    glUseProgram(0);
    width_ = width;
    height_ = height;
    return okStatus();
}

void Renderer::finish() { glFinish(); }

bool Renderer::outputIsFloat(PassId pass) const { return pass != PassId::Image || impl_->floatImage; }

unsigned int Renderer::outputFramebuffer(PassId pass) const {
    if (pass == PassId::Image) return impl_->imageTarget.framebuffer.id();
    const auto& buffer = impl_->buffers[bufferIndex(pass)];
    return buffer ? buffer->slot(slotWritten(impl_->lastFrame < 0 ? 0 : impl_->lastFrame)).framebuffer.id() : 0;
}

void Renderer::readImageRgba8(std::vector<std::uint8_t>& out) const {
    out.resize(static_cast<size_t>(width_) * height_ * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->imageTarget.framebuffer.id());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (impl_->floatImage) {
        // Convert as GL does when writing float colour to a UNORM8 target.
        std::vector<float> floats(out.size());
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, floats.data());
        for (size_t i = 0; i < floats.size(); ++i) out[i] = unorm8(floats[i]);
    } else {
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

void Renderer::readRgba32f(PassId pass, std::vector<float>& out) const {
    out.resize(static_cast<size_t>(width_) * height_ * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, outputFramebuffer(pass));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    if (pass == PassId::Image && !impl_->floatImage) {
        std::vector<std::uint8_t> bytes(out.size());
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        for (size_t i = 0; i < bytes.size(); ++i) out[i] = bytes[i] / 255.0f;
    } else {
        glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, out.data());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

}  // namespace toyhost
