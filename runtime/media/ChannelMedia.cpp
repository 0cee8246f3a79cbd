#include "media/ChannelMedia.h"

#include "core/Defaults.h"

#include <algorithm>

#include "image/ImageFile.h"
#include "manifest/StockMedia.h"
#include "media/LiveAudio.h"

namespace toyhost {

MediaResolver makeMediaResolver(const ManifestDesc& manifest, const MediaOptions& options) {
    MediaResolver media;
    for (const auto& [id, file] : manifest.mediaOverrides) media.setOverride(id, file);
    for (const auto& [id, file] : options.files) media.setOverride(id, file);
    for (const std::filesystem::path& folder : options.folders) media.addSearchFolder(folder);
    return media;
}

std::string channelImageKey(const ChannelDesc& channel) {
    const std::string source = !channel.file.empty() ? "file:" + channel.file.string() : "media:" + channel.media;
    if (channel.kind == ChannelKind::ImageFile || channel.kind == ChannelKind::StockMedia) return source;
    return std::string(channelKindName(channel.kind)) + ":" + source;
}

namespace {
std::string notAvailable(const std::string& what, const std::string& id, const std::string& standIn) {
    return what + " (" + id + ") is not available; using " + standIn +
           ". Give the real file with --media DIR or --media-file ID=FILE";
}
}  // namespace

Result<ChannelMedia> ChannelMedia::load(const ManifestDesc& manifest, const MediaResolver& media,
                                          const MediaOptions& options) {
    ChannelMedia set;
    std::vector<Diagnostic> problems;
    std::map<std::string, bool> failed;  // a key that failed is reported once, at its first channel
    std::vector<const PassDesc*> passes;
    for (const PassDesc& pass : manifest.passes) passes.push_back(&pass);
    if (manifest.sound) passes.push_back(&*manifest.sound);
    for (const PassDesc* passPtr : passes)
        for (int c = 0; c < kChannelCount; ++c) {
            const PassDesc& pass = *passPtr;
            const ChannelDesc& channel = pass.channels[c];
            const std::string key = channelImageKey(channel);
            auto standInNotice = [&](const std::string& message, const std::string& name) {
                Diagnostic notice;
                notice.severity = Severity::Notice;
                notice.code = Code::MediaStandIn;
                notice.message = message;
                notice.pass = passName(pass.id);
                notice.channel = c;
                set.notices_.push_back(std::move(notice));
                set.standIns_.push_back({channel.media.empty() ? channel.file.string() : channel.media, name});
            };
            auto fail = [&](const std::string& source, const Error& error) {
                failed[key] = true;
                Error located = inPass(passName(pass.id), inFile(source, error), c);
                problems.insert(problems.end(), located.diagnostics.begin(), located.diagnostics.end());
            };
            if (failed.count(key)) continue;
            // The real file of a stock input: an override or a search folder's "<hash>.<ext>".
            auto stockFile = [&]() -> std::optional<std::filesystem::path> {
                if (!channel.file.empty()) return channel.file;
                return media.findFile(channel.media);
            };
            const StockInputInfo* stock = channel.media.empty() ? nullptr : findStockInput(channel.media);
            const std::string label = stock ? std::string(stock->name) : channel.media;

            if (channel.kind == ChannelKind::Cubemap) {
                if (set.cubemaps_.count(key)) continue;
                Result<CubeFaces8> faces = Error("unreachable");
                if (std::optional<std::filesystem::path> file = stockFile()) {
                    // Six files (face 0 and its _1.._5 siblings), or one cross or strip image.
                    std::error_code ec;
                    if (std::filesystem::exists(cubemapFacePath(*file, 1), ec)) {
                        faces = loadCubemapFaces(*file);
                    } else if (Result<Image8> image = loadImageFile(*file); !image) {
                        faces = image.error();
                    } else {
                        faces = cubemapFromCross(*image);
                    }
                    if (!faces) {
                        fail(file->string(), faces.error());
                        continue;
                    }
                } else {
                    faces = cubemapStandIn(defaults::kCubemapStandInSize);
                    standInNotice(notAvailable("stock cubemap '" + label + "'", channel.media,
                                               "a sky-like stand-in (" + std::to_string(defaults::kCubemapStandInSize) +
                                                   "x" + std::to_string(defaults::kCubemapStandInSize) + " faces)"),
                                  label);
                }
                set.cubemaps_[key] = std::make_shared<const CubeFaces8>(std::move(*faces));
                continue;
            }
            if (channel.kind == ChannelKind::Volume) {
                if (set.volumes_.count(key)) continue;
                if (std::optional<std::filesystem::path> file = stockFile()) {
                    Result<Volume8> volume = readVolumeFile(*file);
                    if (!volume) {
                        fail(file->string(), volume.error());
                        continue;
                    }
                    set.volumes_[key] = std::make_shared<const Volume8>(std::move(*volume));
                } else {
                    const int side = stock && stock->size > 0 ? stock->size : defaults::kVolumeStandInSize;
                    const int channels = stock ? stock->channels : 4;
                    set.volumes_[key] = std::make_shared<const Volume8>(volumeStandIn(side, channels, 0x5EED));
                    standInNotice(notAvailable("stock volume '" + label + "'", channel.media,
                                               "uniform random bytes of the same size (" + std::to_string(side) + "^3, " +
                                                   std::to_string(channels) + " channel" + (channels > 1 ? "s" : "") + ")"),
                                  label);
                }
                continue;
            }
            if (isTimedMedia(channel.kind)) {
                if (set.timed_.count(key)) continue;
                TimedInput input;
                input.kind = channel.kind;
                if (channel.kind == ChannelKind::Webcam) {
                    if (!options.webcam.empty()) {
                        if (options.webcam.rfind("/dev/", 0) == 0) input.device = options.webcam;
                        else input.file = options.webcam;
                    } else {
                        input.standIn = true;
                        standInNotice("no webcam given (--webcam /dev/video0 or a video file); using a moving "
                                      "stand-in pattern",
                                      "webcam");
                    }
                } else if (channel.kind == ChannelKind::Mic) {
                    if (LiveAudio::isLiveSource(options.mic)) input.device = options.mic;
                    else if (!options.mic.empty()) input.file = options.mic;
                    else {
                        input.standIn = true;
                        standInNotice("no microphone given (--mic FILE); using the synthetic spectrum the site "
                                      "shows when audio is unavailable",
                                      "mic");
                    }
                } else if (std::optional<std::filesystem::path> file = stockFile()) {
                    input.file = *file;
                } else {
                    input.standIn = true;
                    const bool video = channel.kind == ChannelKind::Video;
                    const bool stream = channel.media.rfind("http", 0) == 0;
                    const std::string what = stream ? "music stream" : video ? "video" : "music";
                    if (stream)
                        standInNotice("music stream " + channel.media +
                                          " is not played (toyhost does not stream from the web); using the "
                                          "synthetic spectrum the site shows when audio is unavailable. Give a file "
                                          "with --media-file \"" + channel.media + "=FILE\"",
                                      "music stream");
                    else
                        standInNotice(notAvailable((stock ? "stock " : "") + what + " '" + label + "'", channel.media,
                                                   video ? "a moving stand-in pattern"
                                                         : "the synthetic spectrum the site shows when audio is unavailable"),
                                      label);
                }
                set.timed_[key] = std::move(input);
                continue;
            }
            if (channel.kind != ChannelKind::ImageFile && channel.kind != ChannelKind::StockMedia) continue;
            if (set.images_.count(key)) continue;
            Result<Image8> image = Error("unreachable");
            if (channel.kind == ChannelKind::ImageFile) {
                image = loadImageFile(channel.file);
            } else if (Result<ResolvedMedia> resolved = media.resolve(channel.media); !resolved) {
                image = resolved.error();
            } else {
                if (resolved->standIn) {
                    Diagnostic notice = resolved->notice;
                    notice.pass = passName(pass.id);
                    notice.channel = c;
                    set.notices_.push_back(std::move(notice));
                    const StockMediaInfo* info = findStockMedia(channel.media);
                    set.standIns_.push_back({channel.media, info ? std::string(info->name) : channel.media});
                }
                image = std::move(resolved->image);
            }
            // toyhost's own limit, before any GL (GL's may be smaller; the renderer checks that).
            if (image && (image->width > defaults::kMaxCanvasSide || image->height > defaults::kMaxCanvasSide))
                image = Error("the image is " + std::to_string(image->width) + "x" + std::to_string(image->height) +
                                  ", larger than the " + std::to_string(defaults::kMaxCanvasSide) +
                                  " a side textures may have",
                              Code::ImageTooLarge);
            if (!image) {
                fail(channel.kind == ChannelKind::ImageFile ? channel.file.string() : channel.media, image.error());
                continue;
            }
            set.images_[key] = std::make_shared<const Image8>(std::move(*image));
        }
    if (!problems.empty()) return Error(std::move(problems));
    return set;
}

const CubeFaces8* ChannelMedia::findCubemap(const ChannelDesc& channel) const {
    const auto it = cubemaps_.find(channelImageKey(channel));
    return it == cubemaps_.end() ? nullptr : it->second.get();
}

const Volume8* ChannelMedia::findVolume(const ChannelDesc& channel) const {
    const auto it = volumes_.find(channelImageKey(channel));
    return it == volumes_.end() ? nullptr : it->second.get();
}

const TimedInput* ChannelMedia::findTimed(const ChannelDesc& channel) const {
    const auto it = timed_.find(channelImageKey(channel));
    return it == timed_.end() ? nullptr : &it->second;
}

const Image8* ChannelMedia::find(const ChannelDesc& channel) const {
    const auto it = images_.find(channelImageKey(channel));
    return it == images_.end() ? nullptr : it->second.get();
}

}  // namespace toyhost
