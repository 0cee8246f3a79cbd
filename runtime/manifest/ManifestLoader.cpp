#include "manifest/ManifestLoader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/AtomicFile.h"
#include "core/JsonText.h"
#include "core/NumberText.h"
#include "core/Defaults.h"
#include "core/Suggest.h"
#include "manifest/StockMedia.h"

namespace toyhost {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr long long kMaxSide = defaults::kMaxCanvasSide;

// Collects the problems with their locations so the user sees them together in one run, up to
// defaults::kMaxManifestProblems: then the loops over the manifest stop (full()), and the error ends
// with a note saying so (how many more there are is not known: they were not looked for).
class Problems {
public:
    explicit Problems(std::string file) : file_(std::move(file)) {}
    // `field` is the JSON path; `pass`/`channel` are set when the problem is about one.
    void add(const std::string& field, const std::string& message, Code code = Code::ManifestValue,
             std::optional<PassId> pass = std::nullopt, int channel = -1) {
        if (full()) return;
        diagnostics_.push_back(fieldDiagnostic(file_, field, message, code, pass, channel));
    }
    bool empty() const { return diagnostics_.empty(); }
    bool full() const { return diagnostics_.size() >= defaults::kMaxManifestProblems; }
    Error toError() const {
        std::vector<Diagnostic> all = diagnostics_;
        if (full()) {
            Diagnostic note;
            note.severity = Severity::Notice;
            note.file = file_;
            note.message = "stopped after " + std::to_string(all.size()) +
                           " problems; the rest of the manifest was not checked (fix these and run again)";
            all.push_back(std::move(note));
        }
        return Error(std::move(all));
    }

private:
    std::string file_;
    std::vector<Diagnostic> diagnostics_;
};

std::string quote(const std::string& s) { return "\"" + s + "\""; }

void rejectUnknownFields(const json& object, const std::set<std::string>& known,
                         const std::string& where, Problems& problems) {
    const std::vector<std::string> candidates(known.begin(), known.end());
    for (const auto& [key, _] : object.items()) {
        if (problems.full()) return;
        if (known.count(key)) continue;
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        problems.add(where, "unknown field " + quote(key) + didYouMean(key, candidates) + " (known: " + list + ")",
                     Code::ManifestUnknownField);
    }
}

const std::vector<std::string>& passNames() {
    static const std::vector<std::string> names{"Buffer A", "Buffer B", "Buffer C", "Buffer D", "Cube A", "Image", "Sound"};
    return names;
}

std::optional<PassId> passFromName(const std::string& name) {
    static const std::pair<const char*, PassId> names[] = {
        {"Buffer A", PassId::BufferA}, {"Buffer B", PassId::BufferB},
        {"Buffer C", PassId::BufferC}, {"Buffer D", PassId::BufferD},
        {"Cube A", PassId::CubeA}, {"Image", PassId::Image}};
    for (const auto& [text, id] : names)
        if (name == text) return id;
    return std::nullopt;
}

// "A", "Buffer A" -> 0
std::optional<int> bufferFromName(const std::string& name) {
    std::string letter = name;
    if (letter.rfind("Buffer ", 0) == 0) letter = letter.substr(7);
    if (letter.size() == 1 && letter[0] >= 'A' && letter[0] <= 'D') return letter[0] - 'A';
    return std::nullopt;
}

class Loader {
public:
    Loader(const fs::path& manifestPath)
        : path_(manifestPath), dir_(manifestPath.parent_path()), problems_(manifestPath.string()) {}

    Result<ManifestDesc> load(std::string_view text) {
        Result<json> parsed = parseJsonStrictly(text, path_.string(), Code::ManifestJson);
        if (!parsed) return parsed.error();
        const json root = std::move(*parsed);
        if (!root.is_object()) return fileError(path_.string(), "the manifest must be a JSON object", Code::ManifestJson);

        desc_.manifestPath = path_;
        rejectUnknownFields(root, {"name", "common", "passes", "media", "defaults"}, "", problems_);
        readName(root);
        readDefaults(root);
        readCommon(root);
        readMedia(root);
        readPasses(root);
        checkMediaOverridesUsed();
        if (!problems_.empty()) return problems_.toError();
        std::sort(desc_.passes.begin(), desc_.passes.end(),
                  [](const PassDesc& a, const PassDesc& b) { return a.id < b.id; });
        return std::move(desc_);
    }

private:
    fs::path resolve(const std::string& relative) const {
        fs::path p(relative);
        return (p.is_absolute() ? p : dir_ / p).lexically_normal();
    }

    std::optional<std::string> readString(const json& object, const char* key,
                                          const std::string& where) {
        auto it = object.find(key);
        if (it == object.end()) return std::nullopt;
        if (!it->is_string() || it->get<std::string>().empty()) {
            problems_.add(where, quote(key) + " must be a non-empty string, not " + describeJsonValue(*it), Code::ManifestType);
            return std::nullopt;
        }
        return it->get<std::string>();
    }

    // Reads a GLSL file named by `key`; reports a missing field or unreadable file.
    std::optional<std::pair<fs::path, std::string>> readSourceFile(const json& object, const char* key,
                                                                   const std::string& where) {
        auto name = readString(object, key, where);
        if (!name) return std::nullopt;
        fs::path file = resolve(*name);
        Result<std::string> text = readTextFile(file);
        if (!text) {
            const Diagnostic& cause = text.error().first();
            problems_.add(where.empty() ? key : where + "." + key, file.string() + ": " + cause.message,
                          cause.code);
            return std::nullopt;
        }
        return std::make_pair(file, std::move(*text));
    }

    void readName(const json& root) {
        if (auto name = readString(root, "name", "")) desc_.name = *name;
        else desc_.name = dir_.filename().string();
    }

    // "defaults": {"size": "1280x720" or [1280, 720], "fps": 30, "frames": 600}
    void readDefaults(const json& root) {
        auto it = root.find("defaults");
        if (it == root.end()) return;
        if (!it->is_object()) {
            problems_.add("defaults", "must be an object such as {\"size\": \"1280x720\", \"fps\": 60, \"frames\": 600}",
                          Code::ManifestType);
            return;
        }
        rejectUnknownFields(*it, {"size", "fps", "frames"}, "defaults", problems_);
        RunDefaults& d = desc_.runDefaults;
        if (auto size = it->find("size"); size != it->end()) {
            long long w = 0, h = 0;
            bool parsed = false;
            if (size->is_string()) {
                std::string text = size->get<std::string>();
                while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
                // Read as --size is (core/NumberText.h): decimal digits, no wrap.
                const WholeNumbers read = wholeNumbersIn(text, "xX", 2, 1, kMaxSide);
                parsed = read.problem.empty();
                if (parsed) w = read.values[0], h = read.values[1];
            } else if (size->is_array() && size->size() == 2 && (*size)[0].is_number_integer() &&
                       (*size)[1].is_number_integer()) {
                w = (*size)[0].get<long long>();
                h = (*size)[1].get<long long>();
                parsed = true;
            }
            if (!parsed || w < 1 || h < 1 || w > kMaxSide || h > kMaxSide)
                problems_.add("defaults.size",
                              "must be \"WxH\" or [W, H] with sides 1.." + std::to_string(kMaxSide) + ", not " +
                                  size->dump(),
                              Code::ManifestValue);
            else {
                d.width = static_cast<int>(w);
                d.height = static_cast<int>(h);
            }
        }
        if (auto fps = it->find("fps"); fps != it->end()) {
            if (!fps->is_number() || !std::isfinite(fps->get<double>()) || fps->get<double>() < defaults::kMinFps ||
                fps->get<double>() > defaults::kMaxFps)
                problems_.add("defaults.fps", "must be a number of frames per second (0.001 .. 1000000), not " + fps->dump(),
                              Code::ManifestValue);
            else d.fps = fps->get<double>();
        }
        if (auto frames = it->find("frames"); frames != it->end()) {
            if (!frames->is_number_unsigned() || frames->get<std::uint64_t>() < 1 ||
                frames->get<std::uint64_t>() > static_cast<std::uint64_t>(INT32_MAX))
                problems_.add("defaults.frames", "must be a whole number of frames >= 1, not " + frames->dump(),
                              Code::ManifestValue);
            else d.frames = frames->get<int>();
        }
    }

    void readCommon(const json& root) {
        if (!root.contains("common")) return;
        if (auto source = readSourceFile(root, "common", "")) {
            desc_.commonSource = source->first;
            desc_.commonName = source->first.string();
            desc_.commonCode = std::move(source->second);
        }
    }

    void readMedia(const json& root) {
        auto it = root.find("media");
        if (it == root.end()) return;
        if (!it->is_object()) {
            problems_.add("media", "must be an object mapping stock media ids to files", Code::ManifestType);
            return;
        }
        for (const auto& [id, file] : it->items()) {
            if (problems_.full()) return;
            const std::string where = "media." + quote(id);
            if (!file.is_string()) {
                problems_.add(where, "must be a file path string, not " + describeJsonValue(file), Code::ManifestType);
                continue;
            }
            fs::path resolved = resolve(file.get<std::string>());
            if (Status regular = checkRegularFile(resolved); !regular)
                problems_.add(where, resolved.string() + ": " + regular.error().first().message,
                              regular.error().first().code);
            desc_.mediaOverrides[id] = resolved;
        }
    }

    // A key may be a stock id or the user's own media id (channels may then name it), so only a
    // key that is neither a stock id nor used by any channel is an error (most likely a typo).
    void checkMediaOverridesUsed() {
        for (const auto& [id, file] : desc_.mediaOverrides) {
            if (problems_.full()) return;
            if (!findStockMedia(id) && !mediaRefs_.count(id))
                problems_.add("media." + quote(id), "not a stock media id, and no channel uses it", Code::ManifestUnused);
        }
    }

    void readPasses(const json& root) {
        auto it = root.find("passes");
        if (it == root.end() || !it->is_object() || it->empty()) {
            problems_.add("passes", "must be an object with an \"Image\" pass and optionally "
                                    "\"Buffer A\" .. \"Buffer D\", \"Cube A\", \"Sound\"", Code::ManifestMissing);
            return;
        }
        for (const auto& [name, body] : it->items()) {
            if (problems_.full()) return;
            const std::string where = "passes." + quote(name);
            const bool sound = name == "Sound";
            std::optional<PassId> id = sound ? std::optional<PassId>(PassId::Sound) : passFromName(name);
            if (!id) {
                problems_.add(where,
                              "unknown pass" + didYouMean(name, passNames()) +
                                  " (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound)",
                              Code::ManifestUnknownPass);
                continue;
            }
            if (!body.is_object()) {
                problems_.add(where, "must be an object with \"source\" and \"channels\"", Code::ManifestType, *id);
                continue;
            }
            readPass(*id, body, where, sound);
        }
        if (problems_.full()) return;
        // A misspelt "Image" was reported with its suggestion already: once is enough.
        bool imageMisspelt = false;
        for (const auto& [name, body] : it->items())
            imageMisspelt = imageMisspelt || (!passFromName(name) && closestMatch(name, passNames()) == "Image");
        if (!desc_.find(PassId::Image) && !it->contains("Image") && !imageMisspelt)
            problems_.add("passes", "the \"Image\" pass is missing", Code::ManifestMissing);
        // Buffer references can only be checked once every pass is known.
        for (const auto& [pass, channel, buffer] : bufferRefs_) {
            const char* read = buffer < 0 ? "Cube A" : passName(bufferPass(buffer));
            if (!it->contains(read))
                problems_.add(channelWhere(pass, channel),
                              std::string("reads ") + read + ", which this manifest does not define",
                              Code::ManifestReference, pass, channel);
        }
    }

    static std::string channelWhere(PassId pass, int channel) {
        return "passes." + quote(passName(pass)) + ".channels.iChannel" + std::to_string(channel);
    }

    void readPass(PassId id, const json& body, const std::string& where, bool sound) {
        rejectUnknownFields(body, {"source", "channels"}, where, problems_);
        PassDesc pass;
        pass.id = id;
        if (!body.contains("source")) problems_.add(where, "\"source\" is missing", Code::ManifestMissing, id);
        if (auto source = readSourceFile(body, "source", where)) {
            pass.source = source->first;
            pass.sourceName = source->first.string();
            pass.code = std::move(source->second);
        }
        auto channels = body.find("channels");
        if (channels != body.end()) readChannels(pass, *channels, where + ".channels");
        if (sound) desc_.sound = std::move(pass);
        else desc_.passes.push_back(std::move(pass));
    }

    // Channels are either an object {"iChannel0": {...}} or an array of up to four entries
    // (null = nothing bound).
    void readChannels(PassDesc& pass, const json& channels, const std::string& where) {
        if (channels.is_array()) {
            if (channels.size() > kChannelCount)
                problems_.add(where, "at most 4 channels, got " + std::to_string(channels.size()), Code::ManifestValue,
                              pass.id);
            for (size_t i = 0; i < channels.size() && i < kChannelCount; ++i)
                readChannel(pass, static_cast<int>(i), channels[i]);
            return;
        }
        if (!channels.is_object()) {
            problems_.add(where, "must be an object keyed iChannel0..iChannel3 or an array", Code::ManifestType, pass.id);
            return;
        }
        for (const auto& [key, value] : channels.items()) {
            if (problems_.full()) return;
            int index = -1;
            if (key.size() == 9 && key.rfind("iChannel", 0) == 0 && key[8] >= '0' && key[8] <= '3')
                index = key[8] - '0';
            if (index < 0) {
                static const std::vector<std::string> channelKeys{"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
                problems_.add(where,
                              "unknown channel " + quote(key) + didYouMean(key, channelKeys) +
                                  " (known: iChannel0..iChannel3)",
                              Code::ManifestUnknownField, pass.id);
                continue;
            }
            readChannel(pass, index, value);
        }
    }

    void readChannel(PassDesc& pass, int index, const json& value) {
        const std::string where = channelWhere(pass.id, index);
        ChannelDesc& channel = pass.channels[index];
        if (value.is_null()) return;
        if (!value.is_object()) {
            problems_.add(where, "must be an object such as {\"buffer\": \"A\"}, or null", Code::ManifestType, pass.id, index);
            return;
        }
        // The keys that name a source come from the channel-kind table (manifest/ChannelKinds.h).
        static const std::vector<std::string> sourceKeys = [] {
            std::vector<std::string> keys;
            for (const ChannelKindInfo& kind : channelKinds())
                if (*kind.manifestKey && std::find(keys.begin(), keys.end(), kind.manifestKey) == keys.end())
                    keys.push_back(kind.manifestKey);
            return keys;
        }();
        std::set<std::string> known(sourceKeys.begin(), sourceKeys.end());
        known.insert({"filter", "wrap", "vflip", "kind"});
        rejectUnknownFields(value, known, where, problems_);
        if (problems_.full()) return;
        int sources = 0;
        for (const std::string& key : sourceKeys) sources += value.contains(key);
        // {"bufer": "A"} was reported as a near miss of "buffer": do not also say a source is missing.
        bool sourceMisspelt = false;
        for (const auto& [key, _] : value.items())
            sourceMisspelt = sourceMisspelt || (!known.count(key) && closestMatch(key, sourceKeys));
        if (sources == 0 && sourceMisspelt) return;
        if (sources != 1) {
            std::string list;
            for (const std::string& key : sourceKeys) list += (list.empty() ? "\"" : ", \"") + key + "\"";
            problems_.add(where, "needs exactly one of " + list, Code::ManifestValue, pass.id, index);
            return;
        }
        if (value.contains("kind") && !value.contains("media")) {
            problems_.add(where, "\"kind\" goes with \"media\" only (it says what a stock id the table does not know is)",
                          Code::ManifestValue, pass.id, index);
            return;
        }
        const std::string key = *std::find_if(sourceKeys.begin(), sourceKeys.end(),
                                              [&](const std::string& k) { return value.contains(k); });
        const ChannelKindInfo& kind = *std::find_if(channelKinds().begin(), channelKinds().end(),
                                                    [&](const ChannelKindInfo& k) { return key == k.manifestKey; });
        switch (kind.value) {
            case ManifestValue::None: return;
            case ManifestValue::BufferName:
                if (!readBufferName(pass, index, channel, value, key, where)) return;
                break;
            case ManifestValue::File: {
                auto file = readString(value, key.c_str(), where);
                if (!file) return;  // readString reported the bad value
                channel.kind = kind.kind;
                channel.file = resolve(*file);
                if (Status regular = checkRegularFile(channel.file); !regular)
                    problems_.add(where, key + " " + channel.file.string() + ": " + regular.error().first().message,
                                  regular.error().first().code, pass.id, index);
                break;
            }
            case ManifestValue::True:
                if (value[key] != true) {
                    problems_.add(where, "\"" + key + "\" must be true", Code::ManifestValue, pass.id, index);
                    return;
                }
                channel.kind = kind.kind;
                break;
            case ManifestValue::StockId:
                if (!readMedia(pass, index, channel, value, key, where)) return;
                break;
        }
        readSampler(pass.id, index, channel, value, where);
    }

    // {"buffer": "A".."D"} or {"buffer": "Cube A"}.
    bool readBufferName(PassDesc& pass, int index, ChannelDesc& channel, const json& value, const std::string& key,
                        const std::string& where) {
        auto buffer = readString(value, key.c_str(), where);
        if (!buffer) return false;
        if (*buffer == "Cube A" || *buffer == "CubeA") {
            channel.kind = ChannelKind::CubeBuffer;
            bufferRefs_.push_back({pass.id, index, -1});
            return true;
        }
        std::optional<int> bufferIndex = bufferFromName(*buffer);
        if (!bufferIndex) {
            problems_.add(where, "buffer " + quote(*buffer) + " does not exist (known: A, B, C, D, Cube A)",
                          Code::ManifestReference, pass.id, index);
            return false;
        }
        channel.kind = ChannelKind::Buffer;
        channel.buffer = *bufferIndex;
        bufferRefs_.push_back({pass.id, index, *bufferIndex});
        return true;
    }

    // {"media": ID}: a stock texture, or a stock cubemap, volume, video or music (its kind from the
    // stock table, or from "kind" for an id the table does not know: an import of a newer input).
    bool readMedia(PassDesc& pass, int index, ChannelDesc& channel, const json& value, const std::string& key,
                   const std::string& where) {
        auto media = readString(value, key.c_str(), where);
        if (!media) return false;
        channel.kind = ChannelKind::StockMedia;
        channel.media = *media;
        mediaRefs_.insert(*media);
        const ChannelKindInfo* kind = nullptr;
        if (const StockInputInfo* input = findStockInput(*media))
            kind = channelKindOfMediaKind(stockInputFormName(input->form));
        if (auto named = readString(value, "kind", where)) {
            std::vector<std::string> kinds;
            for (const ChannelKindInfo& info : channelKinds())
                if (*info.mediaKind) kinds.push_back(info.mediaKind);
            kind = channelKindOfMediaKind(*named);
            if (!kind) {
                std::string list;
                for (const std::string& k : kinds) list += (list.empty() ? "" : ", ") + k;
                problems_.add(where, "kind " + quote(*named) + didYouMean(*named, kinds) + " is not one of " + list,
                              Code::ManifestValue, pass.id, index);
                return false;
            }
        }
        if (kind && kind->kind != ChannelKind::StockMedia) {
            channel.kind = kind->kind;
            return true;
        }
        // Any Shadertoy media path is accepted (one the table does not know runs with a flagged
        // stand-in, as imported exports do); other names must be known or given a file.
        const bool mediaPath = media->rfind("/media/a/", 0) == 0 && media->size() > 9;
        const StockMediaInfo* near = desc_.mediaOverrides.count(*media) ? nullptr : nearStockMedia(*media);
        if (near)
            // A one-character slip in a hash would otherwise run with a stand-in of a guessed
            // size, silently replacing a 256x256 noise with a 512x512 photo.
            problems_.add(where,
                          "unknown stock media " + quote(*media) + " (did you mean " + quote(std::string(near->name)) +
                              ", " + stockMediaPath(*near) + "?)",
                          Code::ManifestMediaNearMiss, pass.id, index);
        else if (!mediaPath && !findStockMedia(*media) && !desc_.mediaOverrides.count(*media))
            problems_.add(where,
                          "unknown stock media " + quote(*media) +
                              " (use a /media/a/<hash>.<ext> id, a stock name such as \"Abstract 3\", "
                              "or add it to \"media\" with a file)",
                          Code::ManifestReference, pass.id, index);
        return true;
    }

    void readSampler(PassId pass, int index, ChannelDesc& channel, const json& value, const std::string& where) {
        channel.sampler = defaultSampler(channel.kind);
        channel.samplerType = samplerTypeOf(channel.kind);
        if (channelKindInfo(channel.kind).fixedSampler) {
            for (const char* key : {"filter", "wrap", "vflip"})
                if (value.contains(key))
                    problems_.add(where,
                                  std::string("the ") + channelKindName(channel.kind) + " texture takes no \"" + key +
                                      "\" (it is always " + filterName(channel.sampler.filter) + "/" +
                                      wrapName(channel.sampler.wrap) + ")",
                                  Code::ManifestValue, pass, index);
            return;
        }
        if (auto filter = readString(value, "filter", where)) {
            if (*filter == "nearest") channel.sampler.filter = Filter::Nearest;
            else if (*filter == "linear") channel.sampler.filter = Filter::Linear;
            else if (*filter == "mipmap") channel.sampler.filter = Filter::Mipmap;
            else {
                static const std::vector<std::string> filters{"nearest", "linear", "mipmap"};
                problems_.add(where,
                              "filter " + quote(*filter) + didYouMean(*filter, filters) +
                                  " is not one of nearest, linear, mipmap",
                              Code::ManifestValue, pass, index);
            }
        }
        if (auto wrap = readString(value, "wrap", where)) {
            if (*wrap == "clamp") channel.sampler.wrap = Wrap::Clamp;
            else if (*wrap == "repeat") channel.sampler.wrap = Wrap::Repeat;
            else {
                static const std::vector<std::string> wraps{"clamp", "repeat"};
                problems_.add(where,
                              "wrap " + quote(*wrap) + didYouMean(*wrap, wraps) + " is not one of clamp, repeat",
                              Code::ManifestValue, pass, index);
            }
        }
        if (auto vflip = value.find("vflip"); vflip != value.end()) {
            if (!vflip->is_boolean()) problems_.add(where, "\"vflip\" must be true or false", Code::ManifestType, pass, index);
            else if (!takesVflip(channel.kind))
                problems_.add(where,
                              std::string("\"vflip\" applies only to image textures, cubemaps and videos, not ") +
                                  channelKindName(channel.kind) + " channels",
                              Code::ManifestValue, pass, index);
            else channel.sampler.vflip = vflip->get<bool>();
        }
    }

    struct BufferRef {
        PassId pass;
        int channel;
        int buffer;
    };

    fs::path path_;
    fs::path dir_;
    Problems problems_;
    ManifestDesc desc_;
    std::vector<BufferRef> bufferRefs_;
    std::set<std::string> mediaRefs_;
};

}  // namespace

Result<ManifestDesc> parseManifest(std::string_view jsonText, const fs::path& manifestPath) {
    return Loader(fs::absolute(manifestPath).lexically_normal()).load(jsonText);
}

Result<ManifestDesc> loadManifest(const fs::path& target) {
    std::error_code ec;
    fs::path file = fs::is_directory(target, ec) ? target / "manifest.json" : target;
    Result<std::string> text = readTextFile(file);
    if (!text) return text.error();
    return parseManifest(*text, file);
}

}  // namespace toyhost
