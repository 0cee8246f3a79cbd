#include "render/MediaTextures.h"

#include <cmath>
#include <span>
#include <string>

#include "image/MipChain.h"

namespace toyhost {

namespace {
constexpr int kAudioWidth = 512;
constexpr int kAudioHeight = 2;

void setLevels(GLenum target, const SamplerDesc& sampler) {
    if (sampler.filter != Filter::Mipmap) glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
}
}  // namespace

InputTexture uploadCubemap(const CubeFaces8& faces, const SamplerDesc& sampler) {
    InputTexture out{makeTexture(), faces.size, faces.size};
    glBindTexture(GL_TEXTURE_CUBE_MAP, out.texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> flipped;
    for (int face = 0; face < 6; ++face) {
        const Image8& image = faces.faces[face];
        const std::uint8_t* pixels = image.rgba.data();
        // Rows in memory are bottom first; without vflip the browser uploads the file's rows in
        // file order (top first), as for 2D textures.
        if (!sampler.vflip) {
            copyFlipped(std::span<const std::uint8_t>(image.rgba), image.width, image.height, flipped);
            pixels = flipped.data();
        }
        const GLenum target = GL_TEXTURE_CUBE_MAP_POSITIVE_X + face;
        glTexImage2D(target, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
        if (sampler.filter == Filter::Mipmap) uploadMipLevels(target, pixels, image.width, image.height);
    }
    setLevels(GL_TEXTURE_CUBE_MAP, sampler);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    return out;
}

InputTexture uploadVolume(const Volume8& volume, const SamplerDesc& sampler) {
    InputTexture out{makeTexture(), volume.width, volume.height};
    static const GLenum internal[4] = {GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
    static const GLenum internalFloat[4] = {GL_R32F, GL_RG32F, GL_RGB32F, GL_RGBA32F};
    static const GLenum format[4] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    const int c = std::clamp(volume.channels, 1, 4) - 1;
    glBindTexture(GL_TEXTURE_3D, out.texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, volume.floats ? internalFloat[c] : internal[c], volume.width, volume.height,
                 volume.depth, 0, format[c], volume.floats ? GL_FLOAT : GL_UNSIGNED_BYTE, volume.voxels.data());
    if (sampler.filter == Filter::Mipmap) {
        if (volume.floats) {
            glGenerateMipmap(GL_TEXTURE_3D);
        } else {
            // The exact box filter, as for 2D pictures (llvmpipe's glGenerateMipmap comes out
            // brighter: +0.8 at level 1, +1.4 at level 2 on the stock volumes).
            int level = 1;
            for (const VolumeMipLevel& m : boxMipChain3D(volume.voxels, volume.width, volume.height, volume.depth, c + 1))
                glTexImage3D(GL_TEXTURE_3D, level++, internal[c], m.width, m.height, m.depth, 0, format[c], GL_UNSIGNED_BYTE,
                             m.voxels.data());
        }
    }
    setLevels(GL_TEXTURE_3D, sampler);
    glBindTexture(GL_TEXTURE_3D, 0);
    return out;
}

void siteSilentAudioTexels(double time, int bins, std::array<std::uint8_t, 1024>& texels) {
    const double n = bins;
    for (int j = 0; j < kAudioWidth; ++j) {
        const double x = j / n;
        double f = (0.75 + 0.25 * std::sin(10.0 * j + 13.0 * time)) * std::exp(-3.0 * x);
        if (j < 3) f = std::pow(0.50 + 0.5 * std::sin(6.2831 * time), 4.0) * (1.0 - j / 3.0);
        texels[j] = static_cast<std::uint8_t>(static_cast<int>(std::floor(255.0 * f)) & 255);
    }
    for (int j = 0; j < kAudioWidth; ++j) {
        const double f = 0.5 + 0.15 * std::sin(17.0 * time + 10.0 * 6.2831 * j / n) * std::sin(23.0 * time + 1.9 * j / n);
        texels[kAudioWidth + j] = static_cast<std::uint8_t>(static_cast<int>(std::floor(255.0 * f)) & 255);
    }
}

TimedTexture::TimedTexture(const TimedMedia& media, const SamplerDesc& sampler)
    : media_(media), sampler_(sampler), texture_(makeTexture()) {
    if (channelSource(media.kind) == ChannelSource::Audio) {
        width_ = kAudioWidth;
        height_ = kAudioHeight;
        analyser_ = std::make_unique<AudioAnalyser>();
        window_.resize(static_cast<std::size_t>(analyser_->settings().fftSize));
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, kAudioWidth, kAudioHeight, 0, GL_RED, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
        glBindTexture(GL_TEXTURE_2D, 0);
    } else {
        if (media.video) {
            width_ = media.video->width();
            height_ = media.video->height();
        } else {
            videoStandInFrame(0.0, standInFrame_);
            width_ = standInFrame_.width;
            height_ = standInFrame_.height;
        }
        glBindTexture(GL_TEXTURE_2D, texture_.id());
        const int levels =
            sampler.filter == Filter::Mipmap ? 1 + static_cast<int>(std::floor(std::log2(std::max(width_, height_)))) : 1;
        glTexStorage2D(GL_TEXTURE_2D, levels, GL_RGBA8, width_, height_);
        glBindTexture(GL_TEXTURE_2D, 0);
        if (media.video) {
            // The frame the stream shows now (frame 0 of a stream just opened), without asking for
            // another: a renderer made for a hot reload shares the running stream and must not
            // wait for it here. The first frame asks for its own.
            uploadRgba(media.video->current());
            uploadedVersion_ = media.video->currentVersion();
            return;
        }
    }
    (void)update(0.0);
}

TimedTexture::~TimedTexture() = default;

void TimedTexture::uploadRgba(const Image8& frame) {
    // Rows bottom first: with vflip (every export's video) they go up as they are.
    const std::uint8_t* pixels = frame.rgba.data();
    if (!sampler_.vflip) {
        copyFlipped(std::span<const std::uint8_t>(frame.rgba), frame.width, frame.height, flipped_);
        pixels = flipped_.data();
    }
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, frame.width, frame.height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    if (sampler_.filter == Filter::Mipmap) glGenerateMipmap(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void TimedTexture::uploadAudio() {
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kAudioWidth, kAudioHeight, GL_RED, GL_UNSIGNED_BYTE, audioTexels_.data());
    glBindTexture(GL_TEXTURE_2D, 0);
}

Status TimedTexture::update(double time, const InputWait& wait) {
    waited_ = false;
    if (lastTime_ && *lastTime_ == time) return okStatus();
    lastTime_ = time;
    switch (channelSource(media_.kind)) {
        case ChannelSource::Video: {
            VideoStream* video = media_.video.get();
            if (!video) {
                videoStandInFrame(time, standInFrame_);
                uploadRgba(standInFrame_);
                channelTime_ = media_.kind == ChannelKind::Video ? static_cast<float>(videoStandInPlaybackTime(time)) : 0.0f;
                return okStatus();
            }
            // The site: a video's iChannelTime is its playback time; a webcam's stays 0.
            channelTime_ = media_.kind == ChannelKind::Video ? static_cast<float>(video->playbackTime(time)) : 0.0f;
            const std::uint64_t waitsBefore = video->waits();
            Result<const Image8*> frame = video->frame(video->frameIndexAt(time), wait);
            waited_ = video->waits() != waitsBefore;
            if (!frame) return frame.error();
            if (video->currentVersion() != uploadedVersion_) {
                uploadRgba(**frame);
                uploadedVersion_ = video->currentVersion();
            }
            return okStatus();
        }
        case ChannelSource::Audio: {
            if (media_.live) {
                // A live microphone: the newest samples, whatever the frame's time; the site
                // leaves a mic's iChannelTime at 0.
                media_.live->latest(window_);
                analyser_->analyse(window_);
                audioTexels_ = analyser_->texels();
                channelTime_ = 0.0f;
            } else if (!media_.clip) {
                // The site's arrays: music's hold frequencyBinCount (1024) values, the mic's 512.
                siteSilentAudioTexels(time, media_.kind == ChannelKind::Mic ? 512 : analyser_->settings().fftSize / 2,
                                      audioTexels_);
                channelTime_ = static_cast<float>(10.0 + time);
            } else {
                // Music loops; the site's iChannelTime is the audio's currentTime.
                samplesEndingAt(*media_.clip, time, true, window_);
                analyser_->analyse(window_);
                audioTexels_ = analyser_->texels();
                const double length = media_.clip->seconds();
                channelTime_ = static_cast<float>(length > 0 ? std::fmod(time, length) : 0.0);
            }
            uploadAudio();
            return okStatus();
        }
        default: break;
    }
    return okStatus();
}

}  // namespace toyhost
