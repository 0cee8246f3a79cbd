#include "render/ChannelBindings.h"

#include <new>
#include <string>

#include "core/Defaults.h"
#include "gl/GlContext.h"
#include "image/PixelMemory.h"

namespace toyhost {

namespace {

// Uploads a picture through `textures`. The CPU copies an upload makes (the mip levels, a flipped
// copy) can fail for memory: then an error saying what the picture needed, never std::bad_alloc
// out of the renderer.
Result<GLuint> uploadPicture(InputTextures& textures, const InputTextures::Key& key,
                             const std::function<InputTexture()>& upload, const ChannelDesc& channel,
                             const std::string& needs) {
    try {
        return textures.picture(key, upload).texture.id();
    } catch (const std::bad_alloc&) {
        return notEnoughMemory(channel.media.empty() ? channel.file.string() : channel.media,
                               "uploading it with its mip levels", needs);
    }
}

}  // namespace

GLuint InputTextures::keyboard() {
    if (!keyboard_) keyboard_.emplace();
    return keyboard_->id();
}

const InputTexture& InputTextures::picture(const Key& key, const std::function<InputTexture()>& upload) {
    auto it = pictures_.find(key);
    if (it == pictures_.end()) it = pictures_.emplace(key, upload()).first;
    return it->second;
}

TimedTexture& InputTextures::timed(const Key& key, const TimedMedia& media, const SamplerDesc& sampler,
                                   const char* pass) {
    auto it = timed_.find(key);
    if (it == timed_.end()) it = timed_.emplace(key, Timed{std::make_unique<TimedTexture>(media, sampler), pass}).first;
    return *it->second.texture;
}

bool InputTextures::updateTimed(double time, int frame, RunActivity* activity) {
    bool waited = false;
    for (auto& [key, timed] : timed_) {
        (void)timed.texture->update(time, InputWait{activity, timed.pass, frame});
        waited = waited || timed.texture->waited();
    }
    return waited;
}

void InputTextures::updateKeyboard(std::span<const std::uint8_t> texels) {
    if (keyboard_) keyboard_->update(texels);
}

Result<PassBindings> bindChannels(const PassDesc& pass, const std::array<SamplerDesc, kChannelCount>& samplers,
                                  const ChannelMedia& media, InputTextures& textures, const BindOptions& options) {
    PassBindings out;
    const char* name = passName(pass.id);
    for (int c = 0; c < kChannelCount; ++c) {
        const ChannelDesc& channel = pass.channels[c];
        const SamplerDesc& sampler = samplers[c];
        const ChannelKindInfo& kind = channelKindInfo(channel.kind);
        ChannelBinding& binding = out.channels[c];
        binding.source = kind.source;
        binding.target = textureTarget(channel.samplerType);
        if (kind.source == ChannelSource::Unbound) continue;
        if (options.soundPass && !kind.soundReads)
            return inPass(name,
                          Error(std::string("the Sound pass is rendered before any frame, so it cannot read a ") +
                                    kind.name + " channel",
                                Code::SoundChannel),
                          c);
        binding.sampler = textures.sampler(sampler);
        const InputTextures::Key key{channelImageKey(channel), sampler.vflip, sampler.filter == Filter::Mipmap};
        auto missing = [&](const char* what) {
            return inPass(name, Error(std::string("the channel's ") + what + " was not loaded before rendering", Code::Internal), c);
        };
        switch (kind.source) {
            case ChannelSource::Unbound: break;
            case ChannelSource::Buffer: binding.resolution = options.canvas; break;
            case ChannelSource::CubeBuffer:
                binding.resolution = {float(defaults::kCubeBufferSize), float(defaults::kCubeBufferSize), 1};
                break;
            case ChannelSource::Keyboard:
                binding.texture = textures.keyboard();
                binding.resolution = {float(KeyboardTexture::kWidth), float(KeyboardTexture::kHeight), 1};
                break;
            case ChannelSource::Picture: {
                const Image8* pixels = media.find(channel);
                if (!pixels) return missing("image");
                // GL would refuse it with a bare GL_INVALID_VALUE; say which image and the limit.
                if (const int limit = maxTextureSize(); pixels->width > limit || pixels->height > limit)
                    return inPass(name,
                                  Error("the image is " + std::to_string(pixels->width) + "x" +
                                            std::to_string(pixels->height) + ", larger than this GL allows "
                                            "(GL_MAX_TEXTURE_SIZE " + std::to_string(limit) + ")",
                                        Code::GlTextureSize),
                                  c);
                Result<GLuint> texture = uploadPicture(textures, key, [&] { return uploadImage(*pixels, sampler); }, channel,
                                                       pictureMemoryText(pixels->width, pixels->height));
                if (!texture) return inPass(name, texture.error(), c);
                binding.texture = *texture;
                binding.resolution = {float(pixels->width), float(pixels->height), 1};
                break;
            }
            case ChannelSource::Cubemap: {
                const CubeFaces8* faces = media.findCubemap(channel);
                if (!faces) return missing("cubemap");
                Result<GLuint> texture = uploadPicture(textures, key, [&] { return uploadCubemap(*faces, sampler); }, channel,
                                                       pictureMemoryText(faces->size, faces->size, 6, "faces"));
                if (!texture) return inPass(name, texture.error(), c);
                binding.texture = *texture;
                // The site leaves iChannelResolution at 0 for a cubemap input (only Cube A gets a
                // size): effect.js Paint_Image sets no resolution for it.
                binding.resolution = {0, 0, 0};
                break;
            }
            case ChannelSource::Volume: {
                const Volume8* volume = media.findVolume(channel);
                if (!volume) return missing("volume");
                Result<GLuint> texture =
                    uploadPicture(textures, key, [&] { return uploadVolume(*volume, sampler); }, channel,
                                  formatBytes(volume->voxels.size()) + " of voxels (" + std::to_string(volume->width) + "x" +
                                      std::to_string(volume->height) + "x" + std::to_string(volume->depth) + ")");
                if (!texture) return inPass(name, texture.error(), c);
                binding.texture = *texture;
                binding.resolution = {float(volume->width), float(volume->height), float(volume->depth)};
                break;
            }
            case ChannelSource::Video:
            case ChannelSource::Audio: {
                const TimedMedia* timed = media.findTimed(channel);
                if (!timed) return missing("media");
                TimedTexture& texture = textures.timed(key, *timed, sampler, name);
                binding.texture = texture.texture();
                binding.resolution = texture.resolution();
                binding.timed = &texture;
                out.hasTimed = true;
                break;
            }
        }
    }
    return out;
}

void setChannelUniforms(const UniformLocations& u, const PassBindings& bindings) {
    for (int i = 0; i < kChannelCount; ++i) {
        // Texture unit i carries iChannel i (and iCh i.sampler in the Image pass).
        glUniform1i(u.channel[i], i);
        glUniform1i(u.chSampler[i], i);
        glUniform1i(u.chLoaded[i], bindings.channels[i].source != ChannelSource::Unbound);
        glUniform1f(u.chTime[i], 0.0f);
    }
    glUniform1f(u.sampleRate, static_cast<float>(defaults::kSampleRate));
    // A program keeps its uniforms' values: this 0 is set once per program, and only Mesa's
    // constant folder, which compiled the program before, cannot know it (shader/OpaqueDivisors.h).
    glUniform1ui(u.zero, 0u);
    const float zeros[kChannelCount] = {0, 0, 0, 0};
    glUniform1fv(u.channelTime, kChannelCount, zeros);  // no video or audio inputs
    std::array<float, 3 * kChannelCount> resolutions{};
    for (int i = 0; i < kChannelCount; ++i) {
        for (int k = 0; k < 3; ++k) resolutions[3 * i + k] = bindings.channels[i].resolution[k];
        glUniform3fv(u.chSize[i], 1, bindings.channels[i].resolution.data());
    }
    glUniform3fv(u.channelResolution, kChannelCount, resolutions.data());
}

void setTimedUniforms(const UniformLocations& u, const PassBindings& bindings) {
    if (!bindings.hasTimed) return;
    float times[kChannelCount] = {0, 0, 0, 0};
    for (int c = 0; c < kChannelCount; ++c)
        if (const TimedTexture* timed = bindings.channels[c].timed) {
            times[c] = timed->channelTime();
            glUniform1f(u.chTime[c], times[c]);
        }
    glUniform1fv(u.channelTime, kChannelCount, times);
}

void bindTextures(const PassBindings& bindings, const std::array<GLuint, kChannelCount>& dynamic) {
    for (int c = 0; c < kChannelCount; ++c) {
        const ChannelBinding& binding = bindings.channels[c];
        const bool perFrame = binding.source == ChannelSource::Buffer || binding.source == ChannelSource::CubeBuffer;
        glActiveTexture(GL_TEXTURE0 + c);
        glBindTexture(binding.target, perFrame ? dynamic[c] : binding.texture);
        glBindSampler(c, binding.sampler);
    }
}

}  // namespace toyhost
