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

}  // namespace toyhost
