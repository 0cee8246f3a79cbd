// ManifestDesc: the validated, plain-data description of a shadertoy (passes, channels, sampler
// settings, media overrides). Produced by loadManifest(); consumed by the pass graph and the
// renderer, which never re-check it. No GL needed.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "manifest/ChannelKinds.h"

namespace toyhost {

// Passes in the order Shadertoy renders them each frame: Buffer A, B, C, D, Cube A, then Image.
// (Sound is rendered up front, not per frame: ManifestDesc::sound.)
// PassId::Sound is never in ManifestDesc::passes.
enum class PassId { BufferA = 0, BufferB = 1, BufferC = 2, BufferD = 3, CubeA = 4, Image = 5, Sound = 6 };
inline constexpr int kBufferCount = 4;
inline constexpr int kChannelCount = 4;

const char* passName(PassId id);            // "Buffer A" .. "Cube A", "Image"

// A problem at JSON path `field` of `file` (a manifest or an export), about `pass` / `channel`
// when set.
Diagnostic fieldDiagnostic(std::string file, std::string field, std::string message, Code code,
                           std::optional<PassId> pass = std::nullopt, int channel = -1);
inline bool isBuffer(PassId id) { return static_cast<int>(id) < kBufferCount; }  // Buffer A..D
inline int bufferIndex(PassId id) { return static_cast<int>(id); }  // only for buffers
inline PassId bufferPass(int index) { return static_cast<PassId>(index); }

const char* filterName(Filter f);
const char* wrapName(Wrap w);

struct ChannelDesc {
    ChannelKind kind = ChannelKind::None;
    int buffer = -1;                 // ChannelKind::Buffer: 0..3 = A..D
    std::filesystem::path file;      // ChannelKind::ImageFile: absolute path
    std::string media;               // StockMedia and media kinds: the id as written ("/media/a/<hash>.<ext>")
    SamplerDesc sampler;
    // Its place in its pass's list of inputs in an export (the site creates inputs in that order,
    // which decides the buffer wrap quirk, graph/PassGraph); -1 outside exports.
    int listedAt = -1;
    // The sampler type the header declares. Follows `kind`, except for an unbound channel whose
    // export named a kind toyhost cannot bind (declared as that kind implies, so the shader compiles).
    SamplerType samplerType = SamplerType::Sampler2D;
};

struct PassDesc {
    PassId id = PassId::Image;
    std::filesystem::path source;    // absolute path of the file holding the pass's code
    std::string sourceName;          // how messages name it: the path, or "export.json [Buffer A]"
    std::string code;                // its text, read during loading
    std::array<ChannelDesc, kChannelCount> channels;
    int listedAt = -1;               // its place in an export's list of passes; -1 outside exports
};

// A manifest's own "defaults": the run settings its author chose (a shader written for 1080p
// positions, a simulation that needs 600 frames). The command line overrides each of them.
struct RunDefaults {
    std::optional<int> width;
    std::optional<int> height;
    std::optional<double> fps;
    std::optional<int> frames;
};

struct ManifestDesc {
    std::string name;
    std::filesystem::path manifestPath;            // absolute
    std::optional<std::filesystem::path> commonSource;  // set when the shadertoy has Common
    std::string commonName;                        // how messages name Common's file
    std::string commonCode;
    std::vector<PassDesc> passes;                  // sorted in render order; Image is last
    std::optional<PassDesc> sound;                 // the Sound pass (mainSound), rendered on its own
    std::map<std::string, std::filesystem::path> mediaOverrides;  // stock id -> user file
    std::vector<Diagnostic> notices;               // things the user should know (lenient imports)
    RunDefaults runDefaults;                       // the manifest's "defaults" block

    const PassDesc* find(PassId id) const;
    bool hasBuffer(int index) const { return find(bufferPass(index)) != nullptr; }
    bool hasBuffers() const {
        for (const PassDesc& pass : passes)
            if (isBuffer(pass.id)) return true;
        return false;
    }
    // Buffers or Cube A: passes drawn into ping-pong targets, whose content carries from frame to
    // frame, so a frame depends on every frame before it (a frame range simulates them; a farm
    // starts its shards from checkpoints).
    bool hasStatefulPasses() const { return hasBuffers() || find(PassId::CubeA) != nullptr; }
};

}  // namespace toyhost
