#include "media/ChannelMedia.h"

#include "core/Defaults.h"

#include <algorithm>
#include <functional>
#include <iterator>
#include <mutex>

#include "image/ImageFile.h"
#include "manifest/StockMedia.h"

namespace toyhost {
namespace fs = std::filesystem;

MediaResolver makeMediaResolver(const ManifestDesc& manifest, const MediaOptions& options) {
    MediaResolver media;
    for (const auto& [id, file] : manifest.mediaOverrides) media.setOverride(id, file);
    for (const auto& [id, file] : options.files) media.setOverride(id, file);
    for (const fs::path& folder : options.folders) media.addSearchFolder(folder);
    return media;
}

std::string channelImageKey(const ChannelDesc& channel) {
    const std::string source = !channel.file.empty() ? "file:" + channel.file.string() : "media:" + channel.media;
    if (channel.kind == ChannelKind::ImageFile || channel.kind == ChannelKind::StockMedia) return source;
    return std::string(channelKindName(channel.kind)) + ":" + source;
}

namespace {

std::string sizeText(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// Everything one channel's loader needs to know and to report.
struct ChannelLoad {
    const PassDesc& pass;
    int channel;
    const ChannelDesc& desc;
    const MediaResolver& media;
    const MediaOptions& options;
    const StockMediaInfo* stockTexture;  // a stock 2D texture
    const StockInputInfo* stockInput;    // a stock cubemap, volume, video or music
    std::string label;                   // the stock name, or the id as written

    // The stock id's name in a --media-file suggestion ("Forest"), or the id itself.
    std::string optionName() const { return stockInput ? std::string(stockInput->name) : desc.media; }
    // The real file of a stock input: the manifest's own file, an override or a search folder's.
    std::optional<fs::path> stockFile() const {
        if (!desc.file.empty()) return desc.file;
        return media.findFile(desc.media);
    }
    // A stock id resolved to a file the user supplied (not a file the manifest names itself).
    bool supplied() const { return desc.file.empty() && !desc.media.empty(); }
};

class Loader {
public:
    Loader(std::vector<Diagnostic>& notices, std::vector<StandInUse>& standIns, std::vector<Diagnostic>& problems)
        : notices_(notices), standIns_(standIns), problems_(problems) {}

    // A stand-in is used: `notice` located at the channel, the use listed under `name`.
    void standIn(const ChannelLoad& at, Diagnostic notice, const std::string& name) {
        notice.pass = passName(at.pass.id);
        notice.channel = at.channel;
        notices_.push_back(std::move(notice));
        standIns_.push_back({at.desc.media.empty() ? at.desc.file.string() : at.desc.media, name});
    }
    void standIn(const ChannelLoad& at, const std::string& message, const std::string& name) {
        Diagnostic notice;
        notice.severity = Severity::Notice;
        notice.code = Code::MediaStandIn;
        notice.message = message;
        standIn(at, std::move(notice), name);
    }
    // "stock cubemap 'Forest' (/media/a/...) is not available; using ... Give the real file ..."
    void stockStandIn(const ChannelLoad& at, const std::string& what, const std::string& using_) {
        standIn(at,
                what + " '" + at.label + "' (" + at.desc.media + ") is not available; using " + using_ +
                    ". Give the real file with " + mediaFileOption(at.optionName(), "FILE") + " or --media DIR",
                at.label);
    }

    // Says which file a stock id comes from (`size` "1024x1024", or "" where it has none), and
    // warns when the stock one's size (`stockSize`, "" when unknown) differs.
    void supplied(const ChannelLoad& at, const std::string& what, const fs::path& file, const std::string& size,
                  const std::string& stockSize) {
        if (!at.supplied()) return;
        Diagnostic notice;
        notice.severity = Severity::Notice;
        notice.code = Code::MediaSupplied;
        notice.pass = passName(at.pass.id);
        notice.channel = at.channel;
        notice.message = what + " '" + at.label + "': using the supplied file " + file.string() +
                         (size.empty() ? std::string() : " (" + size + ")");
        notices_.push_back(notice);
        if (size.empty() || stockSize.empty() || size == stockSize) return;
        Diagnostic warning = std::move(notice);
        warning.severity = Severity::Warning;
        warning.code = Code::MediaSizeMismatch;
        warning.message = what + " '" + at.label + "' is " + stockSize + " on shadertoy.com, but the supplied file " +
                          file.string() + " is " + size +
                          ": a shader that depends on the size (texel lookups, hash tables) will not look as on the site";
        notices_.push_back(std::move(warning));
    }

    void fail(const ChannelLoad& at, const std::string& source, const Error& error) {
        Error located = inPass(passName(at.pass.id), inFile(source, error), at.channel);
        problems_.insert(problems_.end(), located.diagnostics.begin(), located.diagnostics.end());
    }

private:
    std::vector<Diagnostic>& notices_;
    std::vector<StandInUse>& standIns_;
    std::vector<Diagnostic>& problems_;
};

// Sources that plans still in use have opened, shared by the plans made after them (the plan of a
// hot reload is made while the running one holds its sources): a camera or a microphone device can
// be opened only once, and decoding the same file again for every reload is wasted work. A file is
// the same while its path, size and modification time are. Entries go when the last plan using
// them does. Thread-safe (plans are made on a watcher's thread).
class OpenSources {
public:
    template <class T, class Open>
    Result<std::shared_ptr<T>> get(const std::string& key, Open open) {
        {
            std::lock_guard lock(mutex_);
            for (auto it = entries_.begin(); it != entries_.end();)
                it = it->second.expired() ? entries_.erase(it) : std::next(it);
            if (auto it = entries_.find(key); it != entries_.end())
                if (std::shared_ptr<void> alive = it->second.lock()) return std::static_pointer_cast<T>(alive);
        }
        Result<std::shared_ptr<T>> opened = open();  // may take seconds: not under the lock
        if (!opened) return opened;
        std::lock_guard lock(mutex_);
        entries_[key] = *opened;
        return opened;
    }

private:
    std::mutex mutex_;
    std::map<std::string, std::weak_ptr<void>> entries_;
};

OpenSources& openSources() {
    static OpenSources sources;
    return sources;
}

// "KIND:PATH:SIZE:MTIME" for a file (so an edited file is opened again), "KIND:DEVICE" for a device.
std::string sourceKey(const std::string& kind, const std::string& source, bool file) {
    if (!file) return kind + ":" + source;
    std::error_code ec;
    const auto size = fs::file_size(source, ec);
    const auto time = fs::last_write_time(source, ec).time_since_epoch().count();
    return kind + ":" + fs::absolute(source, ec).string() + ":" + std::to_string(size) + ":" + std::to_string(time);
}

Result<std::shared_ptr<VideoStream>> openVideo(const std::string& source) {
    const bool device = source.rfind("/dev/", 0) == 0;
    return openSources().get<VideoStream>(sourceKey(device ? "camera" : "video", source, !device), [&] {
        return device ? VideoStream::openDevice(source) : VideoStream::openFile(source);
    });
}

Result<std::shared_ptr<AudioClip>> openAudioFile(const fs::path& file) {
    return openSources().get<AudioClip>(sourceKey("audio", file.string(), true), [&]() -> Result<std::shared_ptr<AudioClip>> {
        Result<AudioClip> clip = decodeAudioFile(file);
        if (!clip) return clip.error();
        return std::make_shared<AudioClip>(std::move(clip).value());
    });
}

Result<std::shared_ptr<LiveAudio>> openLiveAudio(const std::string& spec) {
    return openSources().get<LiveAudio>(sourceKey("live-audio", spec, false), [&]() -> Result<std::shared_ptr<LiveAudio>> {
        Result<std::unique_ptr<LiveAudio>> live = LiveAudio::open(spec);
        if (!live) return live.error();
        return std::shared_ptr<LiveAudio>(std::move(*live));
    });
}

// Each loader returns what the channel shows, or nothing after reporting why.

std::shared_ptr<const Image8> loadPicture(const ChannelLoad& at, Loader& report) {
    Result<Image8> image = Error("unreachable");
    fs::path file;
    if (at.desc.kind == ChannelKind::ImageFile) {
        image = loadImageFile(at.desc.file);
    } else if (Result<ResolvedMedia> resolved = at.media.resolve(at.desc.media); !resolved) {
        image = resolved.error();
    } else {
        if (resolved->standIn) report.standIn(at, resolved->notice, at.stockTexture ? at.label : at.desc.media);
        file = resolved->file;
        image = std::move(resolved).value().image;
    }
    // toyhost's own limit, before any GL (GL's may be smaller; the renderer checks that).
    if (image && (image->width > defaults::kMaxCanvasSide || image->height > defaults::kMaxCanvasSide))
        image = Error("the image is " + sizeText(image->width, image->height) + ", larger than the " +
                          std::to_string(defaults::kMaxCanvasSide) + " a side textures may have",
                      Code::ImageTooLarge);
    if (!image) {
        report.fail(at, at.desc.kind == ChannelKind::ImageFile ? at.desc.file.string() : at.desc.media, image.error());
        return nullptr;
    }
    if (!file.empty())
        report.supplied(at, at.stockTexture ? "stock texture" : "texture", file, sizeText(image->width, image->height),
                        at.stockTexture ? sizeText(at.stockTexture->width, at.stockTexture->height) : std::string());
    return std::make_shared<const Image8>(std::move(image).value());
}

std::shared_ptr<const CubeFaces8> loadCubemap(const ChannelLoad& at, Loader& report) {
    const std::optional<fs::path> file = at.stockFile();
    if (!file) {
        const int side = defaults::kCubemapStandInSize;
        report.stockStandIn(at, "stock cubemap", "a sky-like stand-in (" + sizeText(side, side) + " faces)");
        return std::make_shared<const CubeFaces8>(cubemapStandIn(side));
    }
    // Six files (face 0 and its _1.._5 siblings), or one cross or strip image.
    Result<CubeFaces8> faces = Error("unreachable");
    std::error_code ec;
    if (fs::exists(cubemapFacePath(*file, 1), ec)) faces = loadCubemapFaces(*file);
    else if (Result<Image8> image = loadImageFile(*file); !image) faces = image.error();
    else faces = cubemapFromCross(*image);
    if (!faces) {
        report.fail(at, file->string(), faces.error());
        return nullptr;
    }
    // The table does not know the stock faces' size: nothing to compare.
    report.supplied(at, "stock cubemap", *file, sizeText(faces->size, faces->size) + " faces", "");
    return std::make_shared<const CubeFaces8>(std::move(faces).value());
}

std::shared_ptr<const Volume8> loadVolume(const ChannelLoad& at, Loader& report) {
    const StockInputInfo* stock = at.stockInput;
    const int stockSide = stock && stock->size > 0 ? stock->size : 0;
    const std::optional<fs::path> file = at.stockFile();
    if (!file) {
        const int side = stockSide > 0 ? stockSide : defaults::kVolumeStandInSize;
        const int channels = stock ? stock->channels : 4;
        report.stockStandIn(at, "stock volume",
                            "uniform random bytes of the same size (" + std::to_string(side) + "^3, " +
                                std::to_string(channels) + " channel" + (channels > 1 ? "s" : "") + ")");
        return std::make_shared<const Volume8>(volumeStandIn(side, channels, 0x5EED));
    }
    Result<Volume8> volume = readVolumeFile(*file);
    if (!volume) {
        report.fail(at, file->string(), volume.error());
        return nullptr;
    }
    auto cube = [](int x, int y, int z) { return sizeText(x, y) + "x" + std::to_string(z); };
    report.supplied(at, "stock volume", *file, cube(volume->width, volume->height, volume->depth),
                    stockSide > 0 ? cube(stockSide, stockSide, stockSide) : std::string());
    return std::make_shared<const Volume8>(std::move(volume).value());
}

// A video file or camera, opened (probed, the first frame decoded, the decoder started).
std::optional<TimedMedia> loadVideo(const ChannelLoad& at, Loader& report) {
    TimedMedia timed;
    timed.kind = at.desc.kind;
    Result<std::shared_ptr<VideoStream>> opened = Error("unreachable");
    std::string source;
    if (at.desc.kind == ChannelKind::Webcam) {
        source = at.options.webcam;
        if (source.empty()) {
            report.standIn(at, "no webcam given (--webcam /dev/video0 or a video file); using a moving stand-in pattern",
                           "webcam");
            return timed;
        }
        opened = openVideo(source);
    } else if (std::optional<fs::path> file = at.stockFile()) {
        source = file->string();
        opened = openVideo(file->string());
        if (opened) report.supplied(at, "stock video", *file, "", "");
    } else {
        report.stockStandIn(at, at.stockInput ? "stock video" : "video", "a moving stand-in pattern");
        return timed;
    }
    if (!opened) {
        report.fail(at, source, opened.error());
        return std::nullopt;
    }
    timed.video = std::move(*opened);
    return timed;
}

// Music or a microphone: an audio file decoded whole, or a live source started.
std::optional<TimedMedia> loadAudio(const ChannelLoad& at, Loader& report) {
    TimedMedia timed;
    timed.kind = at.desc.kind;
    std::optional<fs::path> file;
    if (at.desc.kind == ChannelKind::Mic) {
        const std::string& mic = at.options.mic;
        if (LiveAudio::isLiveSource(mic)) {
            Result<std::shared_ptr<LiveAudio>> live = openLiveAudio(mic);
            if (!live) {
                report.fail(at, "", live.error());
                return std::nullopt;
            }
            timed.live = std::move(*live);
            return timed;
        }
        if (mic.empty()) {
            report.standIn(at, "no microphone given (--mic FILE); using the synthetic spectrum the site shows when "
                               "audio is unavailable",
                           "mic");
            return timed;
        }
        file = fs::path(mic);
    } else if (!(file = at.stockFile())) {
        if (at.desc.media.rfind("http", 0) == 0)
            report.standIn(at, "music stream " + at.desc.media +
                                   " is not played (toyhost does not stream from the web); using the synthetic "
                                   "spectrum the site shows when audio is unavailable. Give a file with " +
                                   mediaFileOption(at.desc.media, "FILE"),
                           "music stream");
        else
            report.stockStandIn(at, at.stockInput ? "stock music" : "music",
                                "the synthetic spectrum the site shows when audio is unavailable");
        return timed;
    }
    Result<std::shared_ptr<AudioClip>> clip = openAudioFile(*file);
    if (!clip) {
        report.fail(at, file->string(), clip.error());
        return std::nullopt;
    }
    report.supplied(at, "stock music", *file, "", "");
    timed.clip = std::move(*clip);
    return timed;
}

}  // namespace

Result<ChannelMedia> ChannelMedia::load(const ManifestDesc& manifest, const MediaResolver& media,
                                        const MediaOptions& options) {
    ChannelMedia set;
    std::vector<Diagnostic> problems;
    Loader loader(set.notices_, set.standIns_, problems);
    std::map<std::string, bool> seen;  // each key is loaded (and reported) once, at its first channel
    std::vector<const PassDesc*> passes;
    for (const PassDesc& pass : manifest.passes) passes.push_back(&pass);
    if (manifest.sound) passes.push_back(&*manifest.sound);
    for (const PassDesc* passPtr : passes)
        for (int c = 0; c < kChannelCount; ++c) {
            const PassDesc& pass = *passPtr;
            const ChannelDesc& channel = pass.channels[c];
            const ChannelKindInfo& kind = channelKindInfo(channel.kind);
            if (!isMediaSource(kind.source)) continue;
            // The Sound pass cannot read videos or audio (render/SoundRenderer.h says so): not opened.
            if (pass.id == PassId::Sound && !kind.soundReads) continue;
            const std::string key = channelImageKey(channel);
            if (seen.count(key)) continue;
            seen[key] = true;
            const StockMediaInfo* stockTexture = channel.media.empty() ? nullptr : findStockMedia(channel.media);
            const StockInputInfo* stockInput = channel.media.empty() ? nullptr : findStockInput(channel.media);
            const ChannelLoad at{pass, c, channel, media, options, stockTexture, stockInput,
                                 stockTexture ? std::string(stockTexture->name)
                                 : stockInput ? std::string(stockInput->name)
                                              : channel.media};
            switch (kind.source) {
                case ChannelSource::Picture:
                    if (auto image = loadPicture(at, loader)) set.images_[key] = std::move(image);
                    break;
                case ChannelSource::Cubemap:
                    if (auto faces = loadCubemap(at, loader)) set.cubemaps_[key] = std::move(faces);
                    break;
                case ChannelSource::Volume:
                    if (auto volume = loadVolume(at, loader)) set.volumes_[key] = std::move(volume);
                    break;
                case ChannelSource::Video:
                    if (auto video = loadVideo(at, loader)) set.timed_[key] = std::move(*video);
                    break;
                case ChannelSource::Audio:
                    if (auto audio = loadAudio(at, loader)) set.timed_[key] = std::move(*audio);
                    break;
                default: break;
            }
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

const TimedMedia* ChannelMedia::findTimed(const ChannelDesc& channel) const {
    const auto it = timed_.find(channelImageKey(channel));
    return it == timed_.end() ? nullptr : &it->second;
}

const Image8* ChannelMedia::find(const ChannelDesc& channel) const {
    const auto it = images_.find(channelImageKey(channel));
    return it == images_.end() ? nullptr : it->second.get();
}

}  // namespace toyhost
