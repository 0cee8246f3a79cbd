// MediaTextures: GL textures for the channel kinds beyond 2D pictures: cubemaps (six RGBA8 faces),
// volumes (3D textures of 1-4 8-bit channels) and the inputs that change with time: a video or
// webcam (RGBA8, one upload per frame) and music or a microphone (the site's 512x2 single-channel
// texture: row 0 the FFT magnitude, row 1 the waveform, as WebAudio's analyser gives them).
// Needs a current GL context.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "manifest/ManifestDesc.h"
#include "media/AudioAnalyser.h"
#include "media/AudioClip.h"
#include "media/ChannelMedia.h"
#include "media/LiveAudio.h"
#include "media/VideoStream.h"
#include "render/ChannelTextures.h"

namespace toyhost {

// Six faces; with vflip false (the site's cubemaps) a face file's top row is at t = 0, as GL's
// cube face convention expects. Mip levels are built on the CPU (image/MipChain.h).
InputTexture uploadCubemap(const CubeFaces8& faces, const SamplerDesc& sampler);
// R8, RG8, RGB8 or RGBA8 by the volume's channel count; voxels as stored (x fastest).
InputTexture uploadVolume(const Volume8& volume, const SamplerDesc& sampler);

// The bytes the site puts in a music or microphone texture when no audio plays (muted, or no
// microphone): a decaying spectrum that pulses and a gentle wave (effect.js Paint_Image), with
// iChannelTime = 10 + time. `bins` is the analyser's frequencyBinCount; row 0 is 512 bytes of
// spectrum, row 1 512 bytes of waveform.
void siteSilentAudioTexels(double time, int bins, std::array<std::uint8_t, 1024>& texels);

// A video, webcam, music or mic channel: its texture, updated for each frame's time from a source
// the plan opened (media/ChannelMedia.h): no file or process is opened here, and the only wait is
// for a video decoder that has not decoded the frame yet (published as WaitingForInput).
class TimedTexture {
public:
    TimedTexture(const TimedMedia& media, const SamplerDesc& sampler);
    ~TimedTexture();

    // Brings the texture to iTime `time` (a no-op when the frame shown has not changed); `wait` is
    // published while a video decoder is behind. On an error (a decoder that failed) the last
    // frame stays.
    Status update(double time, const InputWait& wait = {});
    GLuint texture() const { return texture_.id(); }
    std::array<float, 3> resolution() const { return {float(width_), float(height_), 1.0f}; }
    float channelTime() const { return channelTime_; }
    // Whether the last update() had to wait for a video decoder.
    bool waited() const { return waited_; }

private:
    void uploadRgba(const Image8& frame);
    void uploadAudio();

    TimedMedia media_;
    SamplerDesc sampler_;
    GlTexture texture_;
    int width_ = 0;
    int height_ = 0;
    float channelTime_ = 0;
    std::optional<double> lastTime_;
    std::uint64_t uploadedVersion_ = 0;
    bool waited_ = false;  // the video frame (VideoStream::currentVersion) on the texture
    Image8 standInFrame_;
    std::unique_ptr<AudioAnalyser> analyser_;
    std::vector<float> window_;
    std::array<std::uint8_t, 1024> audioTexels_{};
    std::vector<std::uint8_t> flipped_;  // reused for each frame uploaded without vflip
};

}  // namespace toyhost
