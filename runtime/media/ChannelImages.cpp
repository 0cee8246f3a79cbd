#include "media/ChannelImages.h"

#include "core/Defaults.h"

#include <algorithm>

#include "image/ImageFile.h"
#include "manifest/StockMedia.h"

namespace toyhost {

MediaResolver makeMediaResolver(const ManifestDesc& manifest, const MediaOptions& options) {
    MediaResolver media;
    for (const auto& [id, file] : manifest.mediaOverrides) media.setOverride(id, file);
    for (const auto& [id, file] : options.files) media.setOverride(id, file);
    for (const std::filesystem::path& folder : options.folders) media.addSearchFolder(folder);
    return media;
}

std::string channelImageKey(const ChannelDesc& channel) {
    return channel.kind == ChannelKind::ImageFile ? "file:" + channel.file.string() : "media:" + channel.media;
}

Result<ChannelImages> ChannelImages::load(const ManifestDesc& manifest, const MediaResolver& media) {
    ChannelImages set;
    std::vector<Diagnostic> problems;
    std::map<std::string, bool> failed;  // a key that failed is reported once, at its first channel
    for (const PassDesc& pass : manifest.passes)
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& channel = pass.channels[c];
            if (channel.kind != ChannelKind::ImageFile && channel.kind != ChannelKind::StockMedia) continue;
            const std::string key = channelImageKey(channel);
            if (set.images_.count(key) || failed.count(key)) continue;
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
                              "image.too-large");
            if (!image) {
                failed[key] = true;
                const std::string source = channel.kind == ChannelKind::ImageFile ? channel.file.string() : channel.media;
                Error located = inPass(passName(pass.id), inFile(source, image.error()), c);
                problems.insert(problems.end(), located.diagnostics.begin(), located.diagnostics.end());
                continue;
            }
            set.images_[key] = std::make_shared<const Image8>(std::move(*image));
        }
    if (!problems.empty()) return Error(std::move(problems));
    return set;
}

const Image8* ChannelImages::find(const ChannelDesc& channel) const {
    const auto it = images_.find(channelImageKey(channel));
    return it == images_.end() ? nullptr : it->second.get();
}

}  // namespace toyhost
