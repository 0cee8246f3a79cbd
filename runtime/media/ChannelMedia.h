// ChannelMedia: the decoded pixels of every image-file and stock-media channel of a shadertoy,
// loaded before any GL work (each file or stock id once, however many channels use it), with the
// stand-ins that were used. Every problem (missing file, undecodable image) is reported at once.
// CPU only, no GL needed.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/Result.h"
#include "image/Image.h"
#include "manifest/ManifestDesc.h"
#include "media/CubemapFaces.h"
#include "media/MediaResolver.h"
#include "media/VolumeFile.h"

namespace toyhost {

// Where stock media and image files come from, besides the stand-ins.
struct MediaOptions {
    std::vector<std::pair<std::string, std::filesystem::path>> files;  // stock id -> user file (--media-file)
    std::vector<std::filesystem::path> folders;                         // --media DIR, $TOYHOST_MEDIA
    std::string webcam;  // --webcam: a V4L2 device (/dev/video0) or a video file; empty: a stand-in
    // --mic: an audio file, or a live source (alsa:DEVICE, pulse:DEVICE, lavfi:GRAPH); empty: the
    // site's own stand-in (what it shows when audio is unavailable)
    std::string mic;
};

// Where a video, webcam, music or mic channel's content comes from; the renderer opens it.
struct TimedInput {
    ChannelKind kind = ChannelKind::Video;
    std::filesystem::path file;  // a video or audio file; empty with a device or a stand-in
    std::string device;          // webcam: a V4L2 device; mic: a live source (media/LiveAudio.h)
    bool standIn = false;
};

// A resolver set up with the manifest's own "media" entries, then `options` (which win).
MediaResolver makeMediaResolver(const ManifestDesc& manifest, const MediaOptions& options);

struct StandInUse {
    std::string id;    // the media id as the manifest wrote it
    std::string name;  // "Abstract 3", or the id when the table does not know it
};

class ChannelMedia {
public:
    // Decodes every image, cubemap and volume channel of `manifest` (the Sound pass's included)
    // and finds the files of its video and audio channels. Errors name the pass and channel of
    // each problem.
    static Result<ChannelMedia> load(const ManifestDesc& manifest, const MediaResolver& media,
                                      const MediaOptions& options = {});

    // The pixels of an image-file or stock-media channel of the manifest it was loaded for.
    const Image8* find(const ChannelDesc& channel) const;
    const CubeFaces8* findCubemap(const ChannelDesc& channel) const;  // ChannelKind::Cubemap
    const Volume8* findVolume(const ChannelDesc& channel) const;      // ChannelKind::Volume
    const TimedInput* findTimed(const ChannelDesc& channel) const;    // video, webcam, music, mic

    const std::vector<Diagnostic>& notices() const { return notices_; }  // one per stand-in
    const std::vector<StandInUse>& standIns() const { return standIns_; }

private:
    std::map<std::string, std::shared_ptr<const Image8>> images_;  // by channelImageKey
    std::map<std::string, std::shared_ptr<const CubeFaces8>> cubemaps_;
    std::map<std::string, std::shared_ptr<const Volume8>> volumes_;
    std::map<std::string, TimedInput> timed_;
    std::vector<Diagnostic> notices_;
    std::vector<StandInUse> standIns_;
};

// The key two channels share when they show the same picture.
std::string channelImageKey(const ChannelDesc& channel);

}  // namespace toyhost
