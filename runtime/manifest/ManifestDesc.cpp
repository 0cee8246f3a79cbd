#include "manifest/ManifestDesc.h"

namespace toyhost {

Diagnostic fieldDiagnostic(std::string file, std::string field, std::string message, Code code,
                           std::optional<PassId> pass, int channel) {
    Diagnostic d;
    d.code = code;
    d.file = std::move(file);
    d.field = std::move(field);
    d.message = std::move(message);
    if (pass) d.pass = passName(*pass);
    d.channel = channel;
    return d;
}

const char* passName(PassId id) {
    switch (id) {
        case PassId::BufferA: return "Buffer A";
        case PassId::BufferB: return "Buffer B";
        case PassId::BufferC: return "Buffer C";
        case PassId::BufferD: return "Buffer D";
        case PassId::CubeA: return "Cube A";
        case PassId::Image: return "Image";
        case PassId::Sound: return "Sound";
    }
    return "?";
}

const char* filterName(Filter f) {
    switch (f) {
        case Filter::Nearest: return "nearest";
        case Filter::Linear: return "linear";
        case Filter::Mipmap: return "mipmap";
    }
    return "?";
}

const char* wrapName(Wrap w) { return w == Wrap::Clamp ? "clamp" : "repeat"; }

const PassDesc* ManifestDesc::find(PassId id) const {
    for (const PassDesc& pass : passes)
        if (pass.id == id) return &pass;
    return nullptr;
}

SamplerDesc defaultSampler(ChannelKind kind) {
    switch (kind) {
        case ChannelKind::ImageFile:
        case ChannelKind::StockMedia: return {Filter::Mipmap, Wrap::Repeat, true};
        case ChannelKind::Keyboard: return {Filter::Nearest, Wrap::Clamp, false};
        // The site's defaults when such an input is added: cubemaps mipmap/clamp without a flip,
        // volumes mipmap/repeat, videos and audio linear/clamp with vflip.
        case ChannelKind::Cubemap: return {Filter::Mipmap, Wrap::Clamp, false};
        case ChannelKind::Volume: return {Filter::Mipmap, Wrap::Repeat, false};
        case ChannelKind::Video:
        case ChannelKind::Webcam:
        case ChannelKind::Music:
        case ChannelKind::Mic: return {Filter::Linear, Wrap::Clamp, true};
        case ChannelKind::CubeBuffer:
        case ChannelKind::Buffer:
        case ChannelKind::None: break;
    }
    return {Filter::Linear, Wrap::Clamp, false};
}

SamplerType samplerTypeOf(ChannelKind kind) {
    if (kind == ChannelKind::Cubemap || kind == ChannelKind::CubeBuffer) return SamplerType::SamplerCube;
    if (kind == ChannelKind::Volume) return SamplerType::Sampler3D;
    return SamplerType::Sampler2D;
}

const char* channelKindName(ChannelKind kind) {
    switch (kind) {
        case ChannelKind::None: return "none";
        case ChannelKind::Buffer: return "buffer";
        case ChannelKind::ImageFile: return "texture file";
        case ChannelKind::StockMedia: return "texture";
        case ChannelKind::Keyboard: return "keyboard";
        case ChannelKind::CubeBuffer: return "Cube A";
        case ChannelKind::Cubemap: return "cubemap";
        case ChannelKind::Volume: return "volume";
        case ChannelKind::Video: return "video";
        case ChannelKind::Music: return "music";
        case ChannelKind::Webcam: return "webcam";
        case ChannelKind::Mic: return "mic";
    }
    return "?";
}

}  // namespace toyhost
