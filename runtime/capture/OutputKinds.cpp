#include "capture/OutputKinds.h"

#include <algorithm>
#include <array>

namespace toyhost {

namespace {

constexpr std::array<const char*, 1> kPng{".png"};
constexpr std::array<const char*, 1> kExr{".exr"};
// The containers VideoSink names to ffmpeg (capture/VideoSink.cpp, ffmpegArguments).
constexpr std::array<const char*, 4> kVideo{".mp4", ".webm", ".mov", ".mkv"};

// Facts not named in a row are the defaults of OutputKind (a file kind, false otherwise).
constexpr std::array<OutputKind, 4> kKinds{{
    {.format = OutputFormat::Png, .name = "PNG", .extensions = kPng, .tiles = true},
    {.format = OutputFormat::Exr, .name = "EXR", .extensions = kExr, .floats = true, .exrSettings = true,
     .tiles = true},
    {.format = OutputFormat::Video, .name = "video", .extensions = kVideo, .streamed = true, .ffmpeg = true,
     .fixedRate = true, .soundTrack = true},
    {.format = OutputFormat::RawStream, .name = "raw stream", .extensions = {}, .toFile = false, .streamed = true},
}};

}  // namespace

std::span<const OutputKind> outputKinds() { return kKinds; }

const OutputKind& outputKind(OutputFormat format) {
    return *std::find_if(kKinds.begin(), kKinds.end(), [&](const OutputKind& k) { return k.format == format; });
}

const OutputKind* outputKindOfExtension(const std::string& ext) {
    for (const OutputKind& kind : kKinds)
        for (const char* e : kind.extensions)
            if (ext == e) return &kind;
    return nullptr;
}

std::string extensionList(const OutputKind& kind, const char* separator) {
    std::string list;
    for (const char* e : kind.extensions) list += (list.empty() ? "" : separator) + std::string(e);
    return list;
}

std::string extensionsWhere(bool OutputKind::*fact) {
    std::string list;
    for (const OutputKind& kind : kKinds)
        if (kind.*fact && !kind.extensions.empty()) list += (list.empty() ? "" : ", ") + extensionList(kind, ", ");
    return list;
}

std::string tiledKindNames() {
    std::string names;
    for (const OutputKind& kind : kKinds)
        if (kind.tiles) names += (names.empty() ? "" : " or ") + std::string(kind.name);
    return names;
}

std::string outputKindsOffered() {
    std::string offered;
    for (size_t i = 0; i < kKinds.size(); ++i) {
        const OutputKind& kind = kKinds[i];
        const std::string item = !kind.toFile ? std::string(kRawStreamPattern) + " for raw RGBA on stdout"
                                 : kind.extensions.size() == 1
                                     ? std::string(kind.extensions.front())
                                     : "a " + std::string(kind.name) + " " + extensionList(kind, "/");
        offered += (i == 0 ? "" : i + 1 == kKinds.size() ? ", or " : ", ") + item;
    }
    return offered;
}

}  // namespace toyhost
