#include "session/SoundRender.h"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <span>

#include "capture/SoundEncoding.h"
#include "capture/WavFile.h"
#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"
#include "core/InFlight.h"
#include "core/TemporaryFiles.h"
#include "gl/GlObjects.h"
#include "render/ChannelTextures.h"
#include "render/MediaTextures.h"
#include "render/PassProgram.h"
#include "render/RenderTargets.h"
#include "shader/CompilerLog.h"

namespace toyhost {
namespace fs = std::filesystem;

Result<std::vector<float>> renderSound(GlContext& context, const PlayerPlan& plan, const SoundRenderDesc& desc) {
    const ManifestDesc& manifest = plan.manifest;
    if (!manifest.sound) return Error("the shadertoy has no Sound pass (mainSound)", Code::SoundMissing);
    const PassDesc& pass = *manifest.sound;
    const double seconds = desc.seconds > 0 ? desc.seconds : defaults::kSoundSeconds;
    if (Status current = context.makeCurrent(); !current) return current.error();

    Result<PassProgram> program = compilePassProgram(manifest, pass);
    if (!program) return program.error();

    // The channels: pictures only (the site renders the sound before any frame exists).
    std::vector<InputTexture> textures;
    std::array<GLenum, kChannelCount> targets{};
    std::array<GLuint, kChannelCount> ids{};
    std::array<float, 3 * kChannelCount> resolutions{};
    SamplerSet samplers;
    for (int c = 0; c < kChannelCount; ++c) {
        const ChannelDesc& channel = pass.channels[c];
        targets[c] = textureTarget(channel.samplerType);
        if (channel.kind == ChannelKind::None) continue;
        if (const Image8* image = plan.images.find(channel)) {
            textures.push_back(uploadImage(*image, channel.sampler));
            resolutions[3 * c] = float(image->width);
            resolutions[3 * c + 1] = float(image->height);
            resolutions[3 * c + 2] = 1;
        } else if (const CubeFaces8* faces = plan.images.findCubemap(channel)) {
            textures.push_back(uploadCubemap(*faces, channel.sampler));
        } else if (const Volume8* volume = plan.images.findVolume(channel)) {
            textures.push_back(uploadVolume(*volume, channel.sampler));
            resolutions[3 * c] = float(volume->width);
            resolutions[3 * c + 1] = float(volume->height);
            resolutions[3 * c + 2] = float(volume->depth);
        } else {
            return inPass("Sound", Error(std::string("the Sound pass is rendered before any frame, so it cannot read a ") +
                                             channelKindName(channel.kind) + " channel",
                                         Code::SoundChannel),
                          c);
        }
        ids[c] = textures.back().texture.id();
    }

    const int side = defaults::kSoundBlockSide;
    Result<RenderTexture> target = createRenderTexture(side, side, GL_RGBA8, false);
    if (!target) return inPass("Sound", target.error());
    GlVertexArray vertexArray = makeVertexArray();

    const UniformLocations& u = program->uniforms;
    glUseProgram(program->program.id());
    for (int c = 0; c < kChannelCount; ++c) glUniform1i(u.channel[c], c);
    glUniform1f(u.sampleRate, static_cast<float>(defaults::kSampleRate));
    const float zeros[kChannelCount] = {0, 0, 0, 0};
    glUniform1fv(u.channelTime, kChannelCount, zeros);
    glUniform3fv(u.channelResolution, kChannelCount, resolutions.data());
    for (int c = 0; c < kChannelCount; ++c) {
        glActiveTexture(GL_TEXTURE0 + c);
        glBindTexture(targets[c], ids[c]);
        glBindSampler(c, ids[c] ? samplers.get(pass.channels[c].sampler) : 0);
    }

    const std::size_t samples = static_cast<std::size_t>(std::llround(seconds * defaults::kSampleRate));
    const std::size_t perBlock = static_cast<std::size_t>(side) * side;
    std::vector<float> stereo(samples * 2);
    std::vector<std::uint8_t> pixels(perBlock * 4);
    std::vector<float> block(perBlock * 2);
    glBindVertexArray(vertexArray.id());
    glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer.id());
    glViewport(0, 0, side, side);
    glDisable(GL_BLEND);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (std::size_t first = 0; first < samples; first += perBlock) {
        glUniform1f(u.timeOffset, static_cast<float>(static_cast<double>(first) / defaults::kSampleRate));
        glUniform1i(u.sampleOffset, static_cast<GLint>(first));
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glReadPixels(0, 0, side, side, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        decodeSoundBlock(pixels, block);
        const std::size_t count = std::min(perBlock, samples - first);
        std::copy_n(block.begin(), count * 2, stereo.begin() + static_cast<std::ptrdiff_t>(first * 2));
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    if (GLenum error = glGetError(); error != GL_NO_ERROR)
        return Error(std::string("GL: rendering the Sound pass failed: ") + glErrorName(error), Code::GlSound);
    return stereo;
}

Status writeSoundFile(const fs::path& path, const std::vector<float>& stereo) {
    const int rate = static_cast<int>(defaults::kSampleRate);
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension == ".wav") return writeWav16(path, stereo, rate);
    if (!findExecutable("ffmpeg"))
        return fileError(path.string(), "writing " + extension + " audio needs ffmpeg, which was not found in PATH "
                                        "(or write a .wav)", Code::SoundFfmpegMissing);
    TemporaryFiles temp("sound", {"wav", "log"});
    if (!temp.registerAll()) return Error("not written: toyhost is stopping", Code::Interrupted);
    if (Status wav = writeWav16(temp[0], stereo, rate); !wav) return wav;
    // ffmpeg writes next to the target, which is renamed into place only when it succeeded.
    const fs::path partial = temporarySibling(path);
    if (!inflight::addFile(partial)) return Error("not written: toyhost is stopping", Code::Interrupted);
    const std::string format = extension == ".m4a" ? "ipod" : extension.substr(1);
    const std::vector<std::string> args = {"ffmpeg", "-nostdin", "-hide_banner", "-v", "error", "-y", "-i",
                                           "file:" + temp[0].string(), "-f", format, "file:" + partial.string()};
    std::error_code ec;
    auto finish = [&](Status status) {
        fs::remove(partial, ec);
        inflight::removeFile(partial);
        return status;
    };
    Result<ChildProcess> ffmpeg = ChildProcess::spawn(args, temp[1]);
    if (!ffmpeg) return finish(inFile(path.string(), ffmpeg.error()));
    Result<int> exit = ffmpeg->closeAndWait();
    if (!exit || *exit != 0)
        return finish(fileError(path.string(), "ffmpeg could not write " + extension + " audio: " + logTail(temp[1]),
                                Code::SoundEncode));
    fs::rename(partial, path, ec);
    if (ec) return finish(fileError(path.string(), "cannot write the audio file: " + ec.message(), Code::IoWrite));
    return finish(okStatus());
}

}  // namespace toyhost
