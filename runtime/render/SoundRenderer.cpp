#include "render/SoundRenderer.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "capture/SoundEncoding.h"
#include "core/Defaults.h"
#include "gl/GlObjects.h"
#include "render/ChannelBindings.h"
#include "render/PassProgram.h"
#include "render/RenderTargets.h"

namespace toyhost {

Result<std::vector<float>> renderSound(GlContext& context, const ManifestDesc& manifest, const ChannelMedia& media,
                                       const SoundRenderDesc& desc) {
    if (!manifest.sound) return Error("the shadertoy has no Sound pass (mainSound)", Code::SoundMissing);
    const PassDesc& pass = *manifest.sound;
    if (!desc.source) return Error("renderSound: no prepared source (PlayerPlan::soundSource)", Code::Internal);
    const double seconds = desc.seconds > 0 ? desc.seconds : defaults::kSoundSeconds;
    if (Status current = context.makeCurrent(); !current) return current.error();

    // The channels first: a channel the Sound pass cannot read is reported before compiling.
    InputTextures textures;
    std::array<SamplerDesc, kChannelCount> samplers;
    for (int c = 0; c < kChannelCount; ++c) samplers[c] = pass.channels[c].sampler;
    BindOptions bind;
    bind.soundPass = true;
    Result<PassBindings> bindings = bindChannels(pass, samplers, media, textures, bind);
    if (!bindings) return bindings.error();

    GpuActivity& gpu = context.gpuActivity();
    Result<PassProgram> program = [&] {
        GpuActivity::Compiling compiling(gpu, "Sound");
        return compilePassProgram(manifest, pass, *desc.source);
    }();
    if (!program) return program.error();

    const int side = defaults::kSoundBlockSide;
    Result<RenderTexture> target = createRenderTexture(side, side, GL_RGBA8, false);
    if (!target) return inPass("Sound", target.error());
    GlVertexArray vertexArray = makeVertexArray();

    const UniformLocations& u = program->uniforms;
    glUseProgram(program->program.id());
    setChannelUniforms(u, *bindings);
    bindTextures(*bindings, {});

    const std::size_t samples = static_cast<std::size_t>(std::llround(seconds * defaults::kSampleRate));
    const std::size_t perBlock = static_cast<std::size_t>(side) * side;
    // Reserved, not filled: an hour of sound is 1.3 GB, and zero-filling it up front kept the
    // thread from seeing a stop request for seconds under load. Pages are touched block by block.
    std::vector<float> stereo;
    stereo.reserve(samples * 2);
    std::vector<std::uint8_t> pixels(perBlock * 4);
    std::vector<float> block(perBlock * 2);
    glBindVertexArray(vertexArray.id());
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer.id());
    glViewport(0, 0, side, side);
    glDisable(GL_BLEND);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    auto unbind = [] {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glUseProgram(0);
    };
    int blockIndex = 0;
    for (std::size_t first = 0; first < samples; first += perBlock, ++blockIndex) {
        if (desc.stopRequested && desc.stopRequested()) {
            unbind();
            return Error("the Sound pass was not finished: toyhost is stopping", Code::Interrupted);
        }
        glUniform1f(u.timeOffset, static_cast<float>(static_cast<double>(first) / defaults::kSampleRate));
        glUniform1i(u.sampleOffset, static_cast<GLint>(first));
        // GL cannot be interrupted: a watchdog sees which block has been drawing for how long.
        RunActivity* activity = gpu.activity();
        if (activity) activity->begin(RunActivity::Phase::Drawing, "Sound", blockIndex);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glReadPixels(0, 0, side, side, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        if (activity) activity->idle();
        decodeSoundBlock(pixels, block);
        const std::size_t count = std::min(perBlock, samples - first);
        stereo.insert(stereo.end(), block.begin(), block.begin() + static_cast<std::ptrdiff_t>(count * 2));
    }
    unbind();
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: rendering the Sound pass failed: ") + glErrorName(error), Code::GlSound);
    return stereo;
}

}  // namespace toyhost
