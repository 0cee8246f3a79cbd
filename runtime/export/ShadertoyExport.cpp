#include "export/ShadertoyExport.h"

#include "core/JsonText.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>

namespace toyhost {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The shader object inside the accepted document shapes, or null.
const json* shaderObject(const json& document) {
    const json* d = &document;
    if (d->is_array()) {
        if (d->size() != 1) return nullptr;
        d = &(*d)[0];
    }
    if (!d->is_object()) return nullptr;
    if (auto it = d->find("Shader"); it != d->end()) d = &*it;
    if (!d->is_object() || !d->contains("renderpass") || !(*d)["renderpass"].is_array()) return nullptr;
    return d;
}

// An object with a key only exports have: the API form's "Shader", or a shader object's own
// "renderpass", "info" or "ver" (a manifest has none of them; its passes are "passes").
bool hasExportKey(const json& value) {
    if (!value.is_object() || value.contains("passes")) return false;
    for (const char* key : {"Shader", "renderpass", "info", "ver"})
        if (value.contains(key)) return true;
    return false;
}

// "Seascape" (id 4dfGzs), from the shader's info, for naming one shader of several.
std::string shaderLabel(const json& value) {
    const json* d = &value;
    if (auto it = d->find("Shader"); it != d->end() && it->is_object()) d = &*it;
    auto info = d->find("info");
    if (info == d->end() || !info->is_object()) return "a shader without \"info\"";
    auto field = [&](const char* key) {
        auto it = info->find(key);
        return it != info->end() && it->is_string() ? it->get<std::string>() : std::string();
    };
    const std::string name = field("name"), id = field("id");
    if (name.empty()) return id.empty() ? "a shader without a name or id" : "id " + id;
    return "\"" + name + "\"" + (id.empty() ? "" : " (id " + id + ")");
}

// Why `document` is not an export toyhost can run, in the export's own terms.
std::string shapeProblem(const json& document) {
    const json* d = &document;
    std::string where;
    if (d->is_array()) {
        if (d->size() > 1) {
            // The site's array form holds one shader; a list of several (an account's export,
            // or files pasted together) is not one shadertoy.
            std::string names;
            const std::size_t shown = std::min<std::size_t>(d->size(), 3);
            for (std::size_t i = 0; i < shown; ++i)
                names += (i ? ", " : "") + std::string("[") + std::to_string(i) + "] " + shaderLabel((*d)[i]);
            if (shown < d->size()) names += ", ...";
            return "the file holds " + std::to_string(d->size()) + " shaders (" + names +
                   "); toyhost runs one shader per file: export or save each shader on its own";
        }
        if (d->empty()) return "an empty array; the site's form is an array of one shader object";
        d = &(*d)[0];
        where = "[0].";
    }
    if (!d->is_object()) return "expected {\"Shader\": {\"renderpass\": [...]}}";
    if (auto it = d->find("Shader"); it != d->end()) {
        if (!it->is_object()) return where + "Shader: must be an object, not " + describeJsonValue(*it);
        d = &*it;
        where += "Shader.";
    }
    auto passes = d->find("renderpass");
    if (passes == d->end())
        return where + "renderpass: is missing (the list of passes; an export has it beside \"info\")";
    return where + "renderpass: must be an array of passes, not " + describeJsonValue(*passes);
}

std::string text(const json& object, const char* key) {
    auto it = object.find(key);
    if (it == object.end() || it->is_null()) return {};
    if (it->is_string()) return it->get<std::string>();
    return it->dump();
}

// Sampler values arrive as strings ("true", "mipmap") or, in hand-made exports, as JSON values.
std::optional<bool> flag(const json& sampler, const char* key) {
    auto it = sampler.find(key);
    if (it == sampler.end()) return std::nullopt;
    if (it->is_boolean()) return it->get<bool>();
    if (it->is_string()) {
        if (*it == "true") return true;
        if (*it == "false") return false;
    }
    return std::nullopt;
}

// A cubemap input that reads the Cube A pass: output id 41 (API) or "4dX3Rr" (site form), or
// the pass's preview image as src.
bool isCubeBufferInput(const json& input, const std::string& src) {
    if (auto id = input.find("id"); id != input.end()) {
        if (id->is_number_integer() && *id == 41) return true;
        if (id->is_string() && (*id == "4dX3Rr" || *id == "41")) return true;
    }
    return src.find("/media/previz/cubemap") != std::string::npos;
}

class ExportReader {
public:
    ExportReader(const fs::path& path, std::string label) : path_(path), label_(std::move(label)) {}

    Result<ManifestDesc> read(const json& shader) {
        desc_.manifestPath = path_;
        const json& info = shader.contains("info") && shader["info"].is_object() ? shader["info"] : json::object();
        const std::string name = text(info, "name"), id = text(info, "id"), user = text(info, "username");
        desc_.name = name.empty() ? path_.stem().string() : name;
        if (!id.empty()) desc_.name += " (" + id + (user.empty() ? "" : " by " + user) + ")";

        const json& passes = shader["renderpass"];
        for (size_t i = 0; i < passes.size(); ++i) readPass(passes[i], i);
        if (!problems_.empty()) return Error(problems_);
        if (!desc_.find(PassId::Image)) return fileError(label_, "the export has no image pass", Code::ExportMissing);
        std::sort(desc_.passes.begin(), desc_.passes.end(),
                  [](const PassDesc& a, const PassDesc& b) { return a.id < b.id; });
        unbindMissingBuffers();
        return std::move(desc_);
    }

private:
    // `field` is the place in the export (renderpass[3].inputs[1].channel).
    void problem(const std::string& field, const std::string& what, Code code = Code::ExportValue,
                 std::optional<PassId> pass = std::nullopt, int channel = -1) {
        problems_.push_back(fieldDiagnostic(label_, field, what, code, pass, channel));
    }

    void notice(const std::string& what, Code code, std::optional<PassId> pass = std::nullopt,
                int channel = -1) {
        Diagnostic d;
        d.severity = Severity::Notice;
        d.code = code;
        d.file = label_;
        d.message = what;
        if (pass) d.pass = passName(*pass);
        d.channel = channel;
        desc_.notices.push_back(std::move(d));
    }

    std::optional<PassId> passIdentity(const json& pass, const std::string& type, const std::string& where) {
        if (type == "image") return PassId::Image;
        // A buffer is known by its output id; the name is only a fallback for hand-made exports.
        if (auto outputs = pass.find("outputs"); outputs != pass.end() && outputs->is_array())
            for (const json& output : *outputs)
                if (output.is_object() && output.contains("id"))
                    if (int index = bufferIndexFromExportId(output["id"]); index >= 0) return bufferPass(index);
        const std::string name = text(pass, "name");
        if (name.size() == 8 && name.rfind("Buffer ", 0) == 0 && name[7] >= 'A' && name[7] <= 'D')
            return bufferPass(name[7] - 'A');
        problem(where + ".outputs", "buffer pass without a Buffer A..D output id", Code::ExportMissing);
        return std::nullopt;
    }

    void readPass(const json& pass, size_t index) {
        const std::string where = "renderpass[" + std::to_string(index) + "]";
        if (!pass.is_object()) return problem(where, "is not an object", Code::ExportType);
        const std::string type = text(pass, "type");
        const std::string name = text(pass, "name");
        const std::string place = where;
        if (!pass.contains("code") || !pass["code"].is_string())
            return problem(place + ".code", "is missing or not a string", Code::ExportMissing);
        const std::string code = pass["code"].get<std::string>();

        if (type == "common") {
            if (desc_.commonSource) return problem(place, "a second common pass", Code::ExportDuplicate);
            desc_.commonSource = path_;
            desc_.commonName = label_ + " [Common]";
            desc_.commonCode = code;
            return;
        }
        if (type != "image" && type != "buffer" && type != "cubemap" && type != "sound")
            return problem(place + ".type", "unknown pass type \"" + type + "\"", Code::ExportValue);

        const bool sound = type == "sound";
        std::optional<PassId> id = sound ? std::optional<PassId>(PassId::Sound)
                                   : type == "cubemap" ? std::optional<PassId>(PassId::CubeA)
                                                       : passIdentity(pass, type, place);
        if (!id) return;
        if (sound && desc_.sound) return problem(place, "a second Sound pass", Code::ExportDuplicate);
        if (!sound && desc_.find(*id))
            return problem(place, std::string("a second ") + passName(*id) + " pass", Code::ExportDuplicate, *id);
        PassDesc out;
        out.id = *id;
        out.source = path_;
        out.sourceName = label_ + " [" + passName(*id) + "]";
        out.code = code;
        out.listedAt = static_cast<int>(index);
        if (auto inputs = pass.find("inputs"); inputs != pass.end() && inputs->is_array())
            for (size_t k = 0; k < inputs->size(); ++k) {
                readInput(out, (*inputs)[k], place + ".inputs[" + std::to_string(k) + "]");
                if (const json& in = (*inputs)[k]; in.is_object() && in.contains("channel") && in["channel"].is_number_integer()) {
                    const int c = in["channel"].get<int>();
                    if (c >= 0 && c < kChannelCount && out.channels[c].listedAt < 0) out.channels[c].listedAt = static_cast<int>(k);
                }
            }
        else if (inputs != pass.end() && !inputs->is_null())
            problem(place + ".inputs", "must be an array of inputs, not " + describeJsonValue(*inputs),
                    Code::ExportValue, *id);
        if (auto outputs = pass.find("outputs"); outputs != pass.end() && !outputs->is_array() && !outputs->is_null())
            problem(place + ".outputs", "must be an array of outputs, not " + describeJsonValue(*outputs),
                    Code::ExportValue, *id);
        if (sound) desc_.sound = std::move(out);
        else desc_.passes.push_back(std::move(out));
    }

    void readInput(PassDesc& pass, const json& input, const std::string& place) {
        if (!input.is_object()) return problem(place, "is not an object", Code::ExportType, pass.id);
        auto channelIt = input.find("channel");
        if (channelIt == input.end()) return problem(place + ".channel", "is missing", Code::ExportMissing, pass.id);
        if (!channelIt->is_number_integer() || *channelIt < 0 || *channelIt > 3)
            return problem(place + ".channel", channelIt->dump() + " is not 0..3", Code::ExportValue, pass.id);
        const int c = channelIt->get<int>();
        const std::string& where = place;
        const std::string kind = input.contains("ctype") ? text(input, "ctype") : text(input, "type");
        const std::string src = input.contains("src") ? text(input, "src") : text(input, "filepath");
        ChannelDesc& channel = pass.channels[c];
        if (channel.kind != ChannelKind::None)
            return problem(where + ".channel", "iChannel" + std::to_string(c) + " is bound twice", Code::ExportDuplicate,
                           pass.id, c);

        // The ctype says the kind (manifest/ChannelKinds.h); how it names its source, the form.
        const ChannelKindInfo* info = channelKindOfExportType(kind);
        if (!info) {
            notice((kind.empty() ? std::string("untyped") : "\"" + kind + "\"") +
                       " inputs are not a Shadertoy input kind; the channel is left unbound",
                   Code::ExportUnsupportedInput, pass.id, c);
            return;
        }
        if (info->kind == ChannelKind::Buffer) {
            int buffer = bufferIndexFromExportId(input.contains("id") ? input["id"] : json());
            if (buffer < 0) {
                // Site exports name the buffer's preview image: /media/previz/buffer02.png = Buffer C.
                const size_t at = src.find("/media/previz/buffer0");
                if (at != std::string::npos && at + 21 < src.size() && src[at + 21] >= '0' && src[at + 21] <= '3')
                    buffer = src[at + 21] - '0';
            }
            if (buffer < 0)
                return problem(where + ".id", "buffer input with an unknown id " + text(input, "id"), Code::ExportValue,
                               pass.id, c);
            channel.kind = ChannelKind::Buffer;
            channel.buffer = buffer;
        } else if (info->kind == ChannelKind::Cubemap && isCubeBufferInput(input, src)) {
            channel.kind = ChannelKind::CubeBuffer;
        } else if (info->value == ManifestValue::True) {
            channel.kind = info->kind;  // the keyboard, a webcam, a microphone: nothing to name
        } else {
            // A stock texture, cubemap, volume, video or music (a SoundCloud stream plays as music).
            if (src.empty())
                return problem(where + ".src", kind + " input without a src", Code::ExportMissing, pass.id, c);
            channel.kind = info->kind;
            channel.media = src;
        }
        channel.samplerType = samplerTypeOf(channel.kind);
        channel.sampler = defaultSampler(channel.kind);
        if (channelKindInfo(channel.kind).fixedSampler) return;  // the keyboard: always nearest/clamp
        const json& sampler = input.contains("sampler") && input["sampler"].is_object() ? input["sampler"] : json::object();
        const std::string filter = text(sampler, "filter"), wrap = text(sampler, "wrap");
        if (filter == "nearest") channel.sampler.filter = Filter::Nearest;
        else if (filter == "linear") channel.sampler.filter = Filter::Linear;
        else if (filter == "mipmap") channel.sampler.filter = Filter::Mipmap;
        else if (!filter.empty())
            problem(where + ".sampler.filter", "unknown filter \"" + filter + "\"", Code::ExportValue, pass.id, c);
        if (wrap == "clamp") channel.sampler.wrap = Wrap::Clamp;
        else if (wrap == "repeat") channel.sampler.wrap = Wrap::Repeat;
        else if (!wrap.empty()) problem(where + ".sampler.wrap", "unknown wrap \"" + wrap + "\"", Code::ExportValue, pass.id, c);
        // vflip applies to images only; the player ignores it for buffers.
        if (takesVflip(channel.kind))
            if (std::optional<bool> vflip = flag(sampler, "vflip")) channel.sampler.vflip = *vflip;
    }

    // On the site every buffer's textures exist even without its pass, so reading an undefined
    // buffer gives black; here such a channel is left unbound, with a notice.
    // The same for Cube A: the channel stays a samplerCube (the shader compiles) and samples black.
    void unbindMissingBuffers() {
        auto unbind = [&](PassDesc& pass) {
            for (int c = 0; c < kChannelCount; ++c) {
                ChannelDesc& channel = pass.channels[c];
                const bool missingBuffer = channel.kind == ChannelKind::Buffer && !desc_.hasBuffer(channel.buffer);
                const bool missingCube = channel.kind == ChannelKind::CubeBuffer && !desc_.find(PassId::CubeA);
                if (!missingBuffer && !missingCube) continue;
                const std::string what = missingCube ? "Cube A" : passName(bufferPass(channel.buffer));
                notice("reads " + what + ", which the export does not define; the channel is left unbound",
                       Code::ExportMissingBuffer, pass.id, c);
                const SamplerType declared = channel.samplerType;
                channel = ChannelDesc{};
                channel.samplerType = declared;
            }
        };
        for (PassDesc& pass : desc_.passes) unbind(pass);
        if (desc_.sound) unbind(*desc_.sound);
    }

    fs::path path_;
    std::string label_;
    ManifestDesc desc_;
    std::vector<Diagnostic> problems_;
};

}  // namespace

int bufferIndexFromExportId(const json& id) {
    if (id.is_number_integer()) {
        // In 64 bits: 4294967553 must not wrap around to 257 (Buffer A).
        const long long n = id.is_number_unsigned() && id.get<unsigned long long>() > 1000 ? -1 : id.get<long long>();
        return n >= 257 && n <= 260 ? static_cast<int>(n - 257) : -1;
    }
    if (id.is_string()) {
        static const char* siteIds[] = {"4dXGR8", "XsXGR8", "4sXGR8", "XdfGR8"};
        for (int i = 0; i < 4; ++i)
            if (id == siteIds[i]) return i;
        static const char* numericIds[] = {"257", "258", "259", "260"};
        for (int i = 0; i < 4; ++i)
            if (id == numericIds[i]) return i;
    }
    return -1;
}

// An export by its shape, even a broken one: an object with "Shader", "renderpass", "info" or
// "ver" and no "passes", or an array of such objects (the site's form holds one; more than one is
// reported as such). Its problems are then reported as an export's, not a manifest's.
bool isShadertoyExport(const json& document) {
    if (document.is_array())
        return !document.empty() && std::all_of(document.begin(), document.end(), hasExportKey);
    return hasExportKey(document);
}

Result<ManifestDesc> parseShadertoyExport(std::string_view jsonText, const fs::path& exportPath, std::string label) {
    const fs::path path = fs::absolute(exportPath).lexically_normal();
    if (label.empty()) label = path.string();
    Result<json> parsed = parseJsonStrictly(jsonText, label, Code::ExportJson);
    if (!parsed) return parsed.error();
    const json document = std::move(*parsed);
    const json* shader = shaderObject(document);
    if (!shader) {
        const bool several = document.is_array() && document.size() > 1 && isShadertoyExport(document);
        const char* what = several                       ? ""
                           : isShadertoyExport(document) ? "a broken Shadertoy export: "
                                                         : "not a Shadertoy export: ";
        return fileError(label, what + shapeProblem(document), Code::ExportShape);
    }
    return ExportReader(path, std::move(label)).read(*shader);
}

}  // namespace toyhost
