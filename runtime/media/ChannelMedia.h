// ChannelMedia: what every media channel of a shadertoy shows, made ready before any GL work and
// off the GL thread: the decoded pixels of its image, cubemap and volume channels (each file or
// stock id once, however many channels use it), and its videos, cameras, music and microphones
// opened (probed, the first frame decoded, audio files decoded, live sources started), with the
// stand-ins that were used and notices naming supplied files. Every problem (missing file,
// undecodable image, a broken video or music file) is reported at once. CPU only, no GL needed.
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
#include "media/AudioClip.h"
#include "media/CubemapFaces.h"
#include "media/LiveAudio.h"
#include "media/MediaResolver.h"
#include "media/VideoStream.h"
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

// The opened source of a video, webcam, music or mic channel; none of them for a stand-in. Shared:
// channels (and renderers) showing the same source read one decoder, and a plan made while another
// plan holds the source (a hot reload's) gets the same one: a camera or microphone is opened once,
// and a file is decoded again only when it changed (path, size, modification time).
struct TimedMedia {
    ChannelKind kind = ChannelKind::Video;
    std::shared_ptr<VideoStream> video;     // a video file or a camera
    std::shared_ptr<const AudioClip> clip;  // music, or a microphone given as a file
    std::shared_ptr<LiveAudio> live;        // a live microphone
    bool standIn() const { return !video && !clip && !live; }
};

// A resolver set up with the manifest's own "media" entries, then `options` (which win).
MediaResolver makeMediaResolver(const ManifestDesc& manifest, const MediaOptions& options);

struct StandInUse {
    std::string id;    // the media id as the manifest wrote it
    std::string name;  // "Abstract 3", or the id when the table does not know it
};

class ChannelMedia {
public:
    // Decodes every image, cubemap and volume channel of `manifest` (the Sound pass's included) and
    // opens its video and audio channels (not the Sound pass's: it cannot read them). Errors name
    // the pass and channel of each problem; all of them are reported together.
    static Result<ChannelMedia> load(const ManifestDesc& manifest, const MediaResolver& media,
                                     const MediaOptions& options = {});

    // The pixels of an image-file or stock-media channel of the manifest it was loaded for.
    const Image8* find(const ChannelDesc& channel) const;
    const CubeFaces8* findCubemap(const ChannelDesc& channel) const;  // ChannelKind::Cubemap
    const Volume8* findVolume(const ChannelDesc& channel) const;      // ChannelKind::Volume
    const TimedMedia* findTimed(const ChannelDesc& channel) const;    // video, webcam, music, mic

    // One per stand-in used and per supplied stock file (which file it is); warnings where a
    // supplied file's size differs from the stock one's.
    const std::vector<Diagnostic>& notices() const { return notices_; }
    const std::vector<StandInUse>& standIns() const { return standIns_; }

private:
    std::map<std::string, std::shared_ptr<const Image8>> images_;  // by channelImageKey
    std::map<std::string, std::shared_ptr<const CubeFaces8>> cubemaps_;
    std::map<std::string, std::shared_ptr<const Volume8>> volumes_;
    std::map<std::string, TimedMedia> timed_;
    std::vector<Diagnostic> notices_;
    std::vector<StandInUse> standIns_;
};

// The key two channels share when they show the same picture.
std::string channelImageKey(const ChannelDesc& channel);

}  // namespace toyhost
