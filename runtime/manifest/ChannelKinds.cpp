#include "manifest/ChannelKinds.h"

#include <array>
#include <string>

namespace toyhost {

namespace {
using V = ManifestValue;
using S = ChannelSource;
constexpr SamplerType k2D = SamplerType::Sampler2D;
constexpr SamplerType kCube = SamplerType::SamplerCube;
constexpr SamplerType k3D = SamplerType::Sampler3D;
constexpr SamplerDesc kLinearClamp{Filter::Linear, Wrap::Clamp, false};

// The site's defaults (effect.js / the "add input" dialog): textures mipmap/repeat with vflip,
// cubemaps mipmap/clamp without a flip, volumes mipmap/repeat, videos and audio linear/clamp
// with vflip, buffers linear/clamp, the keyboard nearest/clamp (tests/unit/test_manifest_loading).
// The Sound pass is rendered before any frame exists, so it reads only what is there before:
// pictures, cubemaps and volumes.
//  kind                     name            key          value          mediaKind  export types
//      sampler type, default sampler,                  fixed  vflip  timed  sound  source
constexpr std::array<ChannelKindInfo, 12> kKinds{{
    {ChannelKind::None,       "none",         "",         V::None,       "",        "",
         k2D,   kLinearClamp,                           false, false, false, true,  S::Unbound},
    {ChannelKind::Buffer,     "buffer",       "buffer",   V::BufferName, "",        "buffer",
         k2D,   kLinearClamp,                           false, false, false, false, S::Buffer},
    {ChannelKind::ImageFile,  "texture file", "texture",  V::File,       "",        "",
         k2D,   {Filter::Mipmap, Wrap::Repeat, true},   false, true,  false, true,  S::Picture},
    {ChannelKind::StockMedia, "texture",      "media",    V::StockId,    "texture", "texture",
         k2D,   {Filter::Mipmap, Wrap::Repeat, true},   false, true,  false, true,  S::Picture},
    {ChannelKind::Keyboard,   "keyboard",     "keyboard", V::True,       "",        "keyboard",
         k2D,   {Filter::Nearest, Wrap::Clamp, false},  true,  false, false, false, S::Keyboard},
    {ChannelKind::CubeBuffer, "Cube A",       "buffer",   V::BufferName, "",        "",
         kCube, kLinearClamp,                           false, false, false, false, S::CubeBuffer},
    {ChannelKind::Cubemap,    "cubemap",      "cubemap",  V::File,       "cubemap", "cubemap",
         kCube, {Filter::Mipmap, Wrap::Clamp, false},   false, true,  false, true,  S::Cubemap},
    {ChannelKind::Volume,     "volume",       "volume",   V::File,       "volume",  "volume",
         k3D,   {Filter::Mipmap, Wrap::Repeat, false},  false, false, false, true,  S::Volume},
    {ChannelKind::Video,      "video",        "video",    V::File,       "video",   "video",
         k2D,   {Filter::Linear, Wrap::Clamp, true},    false, true,  true,  false, S::Video},
    // A SoundCloud stream ("musicstream") plays as music.
    {ChannelKind::Music,      "music",        "music",    V::File,       "music",   "music musicstream",
         k2D,   {Filter::Linear, Wrap::Clamp, true},    false, false, true,  false, S::Audio},
    {ChannelKind::Webcam,     "webcam",       "webcam",   V::True,       "",        "webcam",
         k2D,   {Filter::Linear, Wrap::Clamp, true},    false, true,  true,  false, S::Video},
    {ChannelKind::Mic,        "mic",          "mic",      V::True,       "",        "mic",
         k2D,   {Filter::Linear, Wrap::Clamp, true},    false, false, true,  false, S::Audio},
}};

constexpr bool inKindOrder() {
    for (std::size_t i = 0; i < kKinds.size(); ++i)
        if (static_cast<std::size_t>(kKinds[i].kind) != i) return false;
    return true;
}
static_assert(inKindOrder(), "kKinds must list every ChannelKind in enum order");

bool holdsWord(std::string_view words, std::string_view word) {
    for (std::size_t start = 0; start <= words.size();) {
        std::size_t end = words.find(' ', start);
        if (end == std::string_view::npos) end = words.size();
        if (!word.empty() && words.substr(start, end - start) == word) return true;
        start = end + 1;
    }
    return false;
}
}  // namespace

std::span<const ChannelKindInfo> channelKinds() { return kKinds; }

const ChannelKindInfo& channelKindInfo(ChannelKind kind) {
    const auto index = static_cast<std::size_t>(kind);
    return index < kKinds.size() ? kKinds[index] : kKinds[0];
}

const ChannelKindInfo* channelKindOfExportType(std::string_view type) {
    for (const ChannelKindInfo& info : kKinds)
        if (holdsWord(info.exportTypes, type)) return &info;
    return nullptr;
}

const ChannelKindInfo* channelKindOfMediaKind(std::string_view mediaKind) {
    for (const ChannelKindInfo& info : kKinds)
        if (!mediaKind.empty() && mediaKind == info.mediaKind) return &info;
    return nullptr;
}

}  // namespace toyhost
