// ChannelImages: the renderer's ImageProvider for real runs. Loads each image file or stock media
// id once (files through stb, stock ids through the MediaResolver) and reports stand-ins through a
// callback. No GL needed.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"
#include "media/Image.h"
#include "media/MediaResolver.h"

namespace toyhost {

class ChannelImages {
public:
    using NoticeSink = std::function<void(const std::string&)>;
    ChannelImages(const MediaResolver& media, NoticeSink notice) : media_(media), notice_(std::move(notice)) {}

    Result<Image8> operator()(const ChannelDesc& channel);

private:
    const MediaResolver& media_;
    NoticeSink notice_;
    std::map<std::string, Image8> cache_;
};

}  // namespace toyhost
