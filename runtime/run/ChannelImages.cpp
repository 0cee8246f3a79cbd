#include "run/ChannelImages.h"

#include "media/ImageFile.h"

namespace toyhost {

Result<Image8> ChannelImages::operator()(const ChannelDesc& channel) {
    const bool file = channel.kind == ChannelKind::ImageFile;
    const std::string key = file ? "file:" + channel.file.string() : "media:" + channel.media;
    if (auto it = cache_.find(key); it != cache_.end()) return it->second;
    Image8 image;
    if (file) {
        Result<Image8> loaded = loadImageFile(channel.file);
        if (!loaded) return loaded.error();
        image = std::move(*loaded);
    } else {
        Result<ResolvedMedia> resolved = media_.resolve(channel.media);
        if (!resolved) return resolved.error();
        if (resolved->standIn && notice_) notice_(resolved->notice);
        image = std::move(resolved->image);
    }
    return cache_.emplace(key, std::move(image)).first->second;
}

}  // namespace toyhost
