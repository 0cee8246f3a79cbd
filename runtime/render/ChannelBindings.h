// ChannelBindings: how a pass's four channels are bound, for every pass that reads channels (the
// buffers, Cube A and Image through the Renderer, the Sound pass through the SoundRenderer): the
// textures of a shadertoy's inputs (InputTextures: uploaded once, shared by every channel that shows
// the same source with the same upload settings), bindChannels() which turns a pass's channels into
// bindings by the channel-kind table's ChannelSource (manifest/ChannelKinds.h), and the uniforms
// and texture units that follow from them. Needs a current GL context.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "manifest/ManifestDesc.h"
#include "media/ChannelMedia.h"
#include "render/ChannelTextures.h"
#include "render/MediaTextures.h"
#include "render/PassProgram.h"

namespace toyhost {

// One channel of a pass as it is bound.
struct ChannelBinding {
    ChannelSource source = ChannelSource::Unbound;
    GLenum target = GL_TEXTURE_2D;  // as the header declares the channel (sampler2D/Cube/3D)
    GLuint texture = 0;             // fixed inputs; buffers and Cube A are given per frame
    GLuint sampler = 0;
    std::array<float, 3> resolution{0, 0, 0};  // iChannelResolution
    TimedTexture* timed = nullptr;  // video and audio: iChannelTime, updated per frame
};

struct PassBindings {
    std::array<ChannelBinding, kChannelCount> channels;
    bool hasTimed = false;
};

// The textures and samplers of a shadertoy's inputs (everything a channel binds but buffers).
class InputTextures {
public:
    // (channelImageKey, vflip, mipmapped): channels that show the same source uploaded the same way
    // share one texture.
    using Key = std::tuple<std::string, bool, bool>;

    GLuint sampler(const SamplerDesc& desc) const { return samplers_.get(desc); }
    GLuint keyboard();  // the 256x3 key-state texture, made on first use
    // The picture, cubemap or volume texture for `key`, made by `upload` the first time.
    const InputTexture& picture(const Key& key, const std::function<InputTexture()>& upload);
    // The video or audio texture for `key`, made the first time; `pass` is the first pass reading it.
    TimedTexture& timed(const Key& key, const TimedMedia& media, const SamplerDesc& sampler, const char* pass);

    // Brings every video and audio texture to iTime `time` (double: the video frame index is
    // floor(time * fps), which a float time gets wrong after about a second). A decoder that is
    // behind is waited for, published on `activity` as WaitingForInput; one that failed keeps its
    // last frame (the failure is the file's). Returns whether anything waited.
    bool updateTimed(double time, int frame, RunActivity* activity);
    void updateKeyboard(std::span<const std::uint8_t> texels);

private:
    struct Timed {
        std::unique_ptr<TimedTexture> texture;
        const char* pass = "";
    };
    SamplerSet samplers_;
    std::optional<KeyboardTexture> keyboard_;
    std::map<Key, InputTexture> pictures_;  // images, cubemaps, volumes
    std::map<Key, Timed> timed_;
};

struct BindOptions {
    std::array<float, 3> canvas{0, 0, 1};  // a buffer's iChannelResolution
    // The Sound pass: rendered before any frame, it reads only the kinds the table says it can
    // (pictures, cubemaps, volumes); any other channel is an error naming it.
    bool soundPass = false;
};

// The bindings of `pass`'s channels, each sampled with `samplers[c]` (the pass graph's, which carry
// the site's sampler quirk; the channel's own for the Sound pass), uploading what `textures` does
// not hold yet from `media`. Errors name the pass and channel.
Result<PassBindings> bindChannels(const PassDesc& pass, const std::array<SamplerDesc, kChannelCount>& samplers,
                                  const ChannelMedia& media, InputTextures& textures, const BindOptions& options = {});

// The uniforms that change only with the program, the bindings or the canvas: texture units
// (iChannelN and the Image pass's iChN on unit N), iChannelResolution, iSampleRate,
// iChannelTime 0, and toyhost_zero (shader/OpaqueDivisors.h). The program must be in use.
void setChannelUniforms(const UniformLocations& uniforms, const PassBindings& bindings);
// iChannelTime of the video and audio channels (after InputTextures::updateTimed).
void setTimedUniforms(const UniformLocations& uniforms, const PassBindings& bindings);
// Binds the channels to texture units 0..3 with their samplers; `dynamic[c]` is the texture of a
// buffer or Cube A channel (ignored for others).
void bindTextures(const PassBindings& bindings, const std::array<GLuint, kChannelCount>& dynamic);

}  // namespace toyhost
