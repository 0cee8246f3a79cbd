#include "manifest/ManifestWriter.h"

#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "manifest/BufferWraps.h"
#include "manifest/StockMedia.h"

namespace toyhost {
namespace fs = std::filesystem;
using nlohmann::ordered_json;

std::string passFileName(PassId id) {
    if (id == PassId::Image) return "image.glsl";
    if (id == PassId::CubeA) return "cube_a.glsl";
    if (id == PassId::Sound) return "sound.glsl";
    return std::string("buffer_") + static_cast<char>('a' + bufferIndex(id)) + ".glsl";
}

namespace {

// `wrap`: the wrap the channel samples with (for a buffer or Cube A, the site's quirk decides it).
ordered_json channelJson(const ChannelDesc& channel, Wrap wrap) {
    const ChannelKindInfo& kind = channelKindInfo(channel.kind);
    const std::string key = kind.manifestKey;
    ordered_json out;
    switch (kind.value) {
        case ManifestValue::None: return nullptr;
        case ManifestValue::True: out[key] = true; break;
        case ManifestValue::BufferName:
            out[key] = channel.kind == ChannelKind::CubeBuffer ? std::string("Cube A")
                                                               : std::string(1, static_cast<char>('A' + channel.buffer));
            break;
        case ManifestValue::StockId: {
            // The site's name ("Lichen") where toyhost knows the texture: the loader accepts it,
            // and a reader of the manifest sees what the channel shows.
            const StockMediaInfo* stock = findStockMedia(channel.media);
            out[key] = stock ? std::string(stock->name) : channel.media;
            break;
        }
        case ManifestValue::File:
            if (!channel.file.empty()) {
                out[key] = channel.file.string();
            } else if (const StockInputInfo* stock = findStockInput(channel.media)) {
                out["media"] = stockInputPath(*stock);
            } else {
                out["media"] = channel.media;  // an id the table does not know: say what it is
                out["kind"] = kind.mediaKind;
            }
            break;
    }
    if (kind.fixedSampler) return out;
    out["filter"] = filterName(channel.sampler.filter);
    out["wrap"] = wrapName(wrap);
    if (kind.vflip) out["vflip"] = channel.sampler.vflip;
    return out;
}

Status writeText(const fs::path& path, const std::string& text) {
    return writeBytesAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace

std::string manifestJson(const ManifestDesc& desc) {
    ordered_json root;
    root["name"] = desc.name;
    if (desc.commonSource) root["common"] = "common.glsl";
    ordered_json passes = ordered_json::object();
    // Every channel reading a buffer or Cube A is written with the wrap that buffer ends up with:
    // an export's is decided by its listed order (manifest/BufferWraps.h), which a manifest cannot
    // hold; with all readers agreeing, the manifest's own order gives the same wrap.
    const BufferWraps wraps = siteBufferWraps(desc);
    std::vector<const PassDesc*> all;
    for (const PassDesc& pass : desc.passes) all.push_back(&pass);
    if (desc.sound) all.push_back(&*desc.sound);
    for (const PassDesc* passPtr : all) {
        const PassDesc& pass = *passPtr;
        ordered_json body;
        body["source"] = passFileName(pass.id);
        ordered_json channels = ordered_json::object();
        for (int c = 0; c < kChannelCount; ++c)
            if (pass.channels[c].kind != ChannelKind::None)
                channels["iChannel" + std::to_string(c)] = channelJson(pass.channels[c], wrapSampled(wraps, pass.channels[c]));
        if (!channels.empty()) body["channels"] = channels;
        passes[passName(pass.id)] = body;
    }
    root["passes"] = passes;
    if (!desc.mediaOverrides.empty()) {
        ordered_json media = ordered_json::object();
        for (const auto& [id, file] : desc.mediaOverrides) media[id] = file.string();
        root["media"] = media;
    }
    return root.dump(2) + "\n";
}

Status writeManifestFolder(const ManifestDesc& desc, const fs::path& dir, bool overwrite) {
    std::error_code ec;
    if (!overwrite && fs::exists(dir / "manifest.json", ec))
        return fileError((dir / "manifest.json").string(), "already exists (use --force to overwrite)", Code::IoExists);
    if (desc.commonSource)
        if (Status s = writeText(dir / "common.glsl", desc.commonCode); !s) return s;
    for (const PassDesc& pass : desc.passes)
        if (Status s = writeText(dir / passFileName(pass.id), pass.code); !s) return s;
    if (desc.sound)
        if (Status s = writeText(dir / passFileName(PassId::Sound), desc.sound->code); !s) return s;
    // The manifest last: a folder with a manifest.json is a complete import.
    return writeText(dir / "manifest.json", manifestJson(desc));
}

}  // namespace toyhost
