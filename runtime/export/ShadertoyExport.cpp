#include "export/ShadertoyExport.h"

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

class ExportReader {
public:
    explicit ExportReader(const fs::path& path) : path_(path), label_(path.string()) {}

    Result<ManifestDesc> read(const json& shader) {
        desc_.manifestPath = path_;
        const json& info = shader.contains("info") && shader["info"].is_object() ? shader["info"] : json::object();
        const std::string name = text(info, "name"), id = text(info, "id"), user = text(info, "username");
        desc_.name = name.empty() ? path_.stem().string() : name;
        if (!id.empty()) desc_.name += " (" + id + (user.empty() ? "" : " by " + user) + ")";

        const json& passes = shader["renderpass"];
        for (size_t i = 0; i < passes.size(); ++i) readPass(passes[i], i);
        if (!problems_.empty()) return joinProblems();
        if (!desc_.find(PassId::Image)) return Error{label_ + ": the export has no image pass"};
        std::sort(desc_.passes.begin(), desc_.passes.end(),
                  [](const PassDesc& a, const PassDesc& b) { return a.id < b.id; });
        unbindMissingBuffers();
        return std::move(desc_);
    }

private:
    Error joinProblems() const {
        std::string all;
        for (const std::string& p : problems_) all += (all.empty() ? "" : "\n") + p;
        return Error{all};
    }

    void problem(const std::string& where, const std::string& what) {
        problems_.push_back(label_ + ": " + where + ": " + what);
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
        problem(where, "buffer pass without a Buffer A..D output id");
        return std::nullopt;
    }

    void readPass(const json& pass, size_t index) {
        const std::string where = "renderpass[" + std::to_string(index) + "]";
        if (!pass.is_object()) return problem(where, "is not an object");
        const std::string type = text(pass, "type");
        const std::string name = text(pass, "name");
        const std::string place = where + (name.empty() ? "" : " \"" + name + "\"");
        if (!pass.contains("code") || !pass["code"].is_string()) return problem(place, "has no \"code\" string");
        const std::string code = pass["code"].get<std::string>();

        if (type == "common") {
            if (desc_.commonSource) return problem(place, "a second common pass");
            desc_.commonSource = path_;
            desc_.commonName = label_ + " [Common]";
            desc_.commonCode = code;
            return;
        }
        if (type == "sound") {
            desc_.notices.push_back(label_ + ": the Sound pass is skipped (toyhost renders no audio)");
            return;
        }
        if (type == "cubemap") return problem(place, "Cube A passes are not supported yet");
        if (type != "image" && type != "buffer") return problem(place, "unknown pass type \"" + type + "\"");

        std::optional<PassId> id = passIdentity(pass, type, place);
        if (!id) return;
        if (desc_.find(*id)) return problem(place, std::string("a second ") + passName(*id) + " pass");
        PassDesc out;
        out.id = *id;
        out.source = path_;
        out.sourceName = label_ + " [" + passName(*id) + "]";
        out.code = code;
        if (auto inputs = pass.find("inputs"); inputs != pass.end() && inputs->is_array())
            for (const json& input : *inputs) readInput(out, input, place);
        desc_.passes.push_back(std::move(out));
    }

    void readInput(PassDesc& pass, const json& input, const std::string& place) {
        if (!input.is_object()) return problem(place, "an input is not an object");
        auto channelIt = input.find("channel");
        if (channelIt == input.end() || !channelIt->is_number_integer() || *channelIt < 0 || *channelIt > 3)
            return problem(place, "an input has no channel 0..3");
        const int c = channelIt->get<int>();
        const std::string where = std::string(passName(pass.id)) + " / iChannel" + std::to_string(c);
        const std::string kind = input.contains("ctype") ? text(input, "ctype") : text(input, "type");
        const std::string src = input.contains("src") ? text(input, "src") : text(input, "filepath");
        ChannelDesc& channel = pass.channels[c];
        if (channel.kind != ChannelKind::None) return problem(where, "bound twice");

        if (kind == "buffer") {
            int buffer = bufferIndexFromExportId(input.contains("id") ? input["id"] : json());
            if (buffer < 0) {
                // Site exports name the buffer's preview image: /media/previz/buffer02.png = Buffer C.
                const size_t at = src.find("/media/previz/buffer0");
                if (at != std::string::npos && at + 21 < src.size() && src[at + 21] >= '0' && src[at + 21] <= '3')
                    buffer = src[at + 21] - '0';
            }
            if (buffer < 0) return problem(where, "buffer input with an unknown id " + text(input, "id"));
            channel.kind = ChannelKind::Buffer;
            channel.buffer = buffer;
        } else if (kind == "keyboard") {
            channel.kind = ChannelKind::Keyboard;
        } else if (kind == "texture") {
            if (src.empty()) return problem(where, "texture input without a src");
            channel.kind = ChannelKind::StockMedia;
            channel.media = src;
        } else {
            desc_.notices.push_back(label_ + ": " + where + ": " + (kind.empty() ? "untyped" : kind) +
                                    " inputs are not supported; the channel is left unbound");
            return;
        }
        channel.sampler = defaultSampler(channel.kind);
        if (channel.kind == ChannelKind::Keyboard) return;  // always nearest/clamp
        const json& sampler = input.contains("sampler") && input["sampler"].is_object() ? input["sampler"] : json::object();
        const std::string filter = text(sampler, "filter"), wrap = text(sampler, "wrap");
        if (filter == "nearest") channel.sampler.filter = Filter::Nearest;
        else if (filter == "linear") channel.sampler.filter = Filter::Linear;
        else if (filter == "mipmap") channel.sampler.filter = Filter::Mipmap;
        else if (!filter.empty()) problem(where, "unknown filter \"" + filter + "\"");
        if (wrap == "clamp") channel.sampler.wrap = Wrap::Clamp;
        else if (wrap == "repeat") channel.sampler.wrap = Wrap::Repeat;
        else if (!wrap.empty()) problem(where, "unknown wrap \"" + wrap + "\"");
        // vflip applies to images only; the player ignores it for buffers.
        if (channel.kind == ChannelKind::StockMedia)
            if (std::optional<bool> vflip = flag(sampler, "vflip")) channel.sampler.vflip = *vflip;
    }

    // On the site every buffer's textures exist even without its pass, so reading an undefined
    // buffer gives black; here such a channel is left unbound, with a notice.
    void unbindMissingBuffers() {
        for (PassDesc& pass : desc_.passes)
            for (int c = 0; c < kChannelCount; ++c) {
                ChannelDesc& channel = pass.channels[c];
                if (channel.kind != ChannelKind::Buffer || desc_.hasBuffer(channel.buffer)) continue;
                desc_.notices.push_back(label_ + ": " + passName(pass.id) + " / iChannel" + std::to_string(c) + " reads " +
                                        passName(bufferPass(channel.buffer)) +
                                        ", which the export does not define; the channel is left unbound");
                channel = ChannelDesc{};
            }
    }

    fs::path path_;
    std::string label_;
    ManifestDesc desc_;
    std::vector<std::string> problems_;
};

}  // namespace

int bufferIndexFromExportId(const json& id) {
    if (id.is_number_integer()) {
        const int n = id.get<int>();
        return n >= 257 && n <= 260 ? n - 257 : -1;
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

bool isShadertoyExport(const json& document) { return shaderObject(document) != nullptr; }

Result<ManifestDesc> parseShadertoyExport(std::string_view jsonText, const fs::path& exportPath) {
    const fs::path path = fs::absolute(exportPath).lexically_normal();
    json document;
    try {
        document = json::parse(jsonText);
    } catch (const json::parse_error& e) {
        return Error{path.string() + ": invalid JSON: " + e.what()};
    }
    const json* shader = shaderObject(document);
    if (!shader) return Error{path.string() + ": not a Shadertoy export (expected {\"Shader\": {\"renderpass\": [...]}})"};
    return ExportReader(path).read(*shader);
}

}  // namespace toyhost
