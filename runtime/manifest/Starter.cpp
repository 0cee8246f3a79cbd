#include "manifest/Starter.h"

#include <cctype>
#include <span>
#include <vector>

#include "core/AtomicFile.h"
#include "core/JsonText.h"
#include "manifest/ManifestWriter.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

// The code shadertoy.com puts in a new shader's Image tab.
constexpr std::string_view kSiteImageCode = R"(void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    // Normalized pixel coordinates (from 0 to 1)
    vec2 uv = fragCoord/iResolution.xy;

    // Time varying pixel color
    vec3 col = 0.5 + 0.5*cos(iTime+uv.xyx+vec3(0,2,4));

    // Output to screen
    fragColor = vec4(col,1.0);
}
)";

// The code shadertoy.com puts in a new Buffer tab.
constexpr std::string_view kSiteBufferCode = R"(void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    fragColor = vec4(0.0,0.0,1.0,1.0);
}
)";

// Buffer A of a multi-pass starter: feedback that shows itself working.
constexpr std::string_view kFeedbackBufferCode = R"(// Buffer A reads its own previous frame (iChannel0 = Buffer A): it fades what was there and paints
// a dot that follows the mouse while a button is held (else it circles), so the trail you see is
// the feedback working. Replace it with your simulation.
void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    vec2 uv = fragCoord/iResolution.xy;
    vec3 previous = texture(iChannel0, uv).rgb;
    vec2 centre = iMouse.z > 0.0 ? iMouse.xy
                                 : iResolution.xy*(0.5 + 0.35*vec2(cos(iTime), sin(1.3*iTime)));
    float ink = smoothstep(0.04, 0.03, length(fragCoord - centre)/iResolution.y);
    vec3 col = 0.5 + 0.5*cos(iTime+vec3(0,2,4));
    fragColor = vec4(mix(previous*0.985, col, ink), 1.0);
}
)";

constexpr std::string_view kShowBufferCode = R"(// Image shows Buffer A (iChannel0).
void mainImage( out vec4 fragColor, in vec2 fragCoord )
{
    vec2 uv = fragCoord/iResolution.xy;
    fragColor = vec4(texture(iChannel0, uv).rgb, 1.0);
}
)";

constexpr std::string_view kCommonCode =
    "// Common: code shared by every pass, pasted before each pass's own code.\n";

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string trimmed(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    return std::string(text);
}

std::string readme(const ManifestDesc& desc) {
    std::string passes;
    if (desc.commonSource) passes += "- `common.glsl`: Common, pasted before every pass\n";
    for (const PassDesc& pass : desc.passes) {
        passes += "- `" + passFileName(pass.id) + "`: " + passName(pass.id);
        if (pass.id == PassId::BufferA && desc.passes.size() > 1) passes += " (reads its own previous frame)";
        if (pass.id == PassId::Image && desc.hasBuffer(0)) passes += " (shows Buffer A)";
        passes += "\n";
    }
    return "# " + desc.name +
           "\n\nWhat it shows, in one line.\n\n"
           "## Run it\n\n"
           "```sh\n"
           "toyhost run " + desc.name + "                 # a window (mouse and keyboard as on the site; edits reload)\n"
           "toyhost run " + desc.name + " --headless --watch --out frame_%04d.png --frames 60   # again after every edit\n"
           "```\n\n"
           "## Files\n\n" + passes +
           "- `manifest.json`: the passes and what each `iChannelN` reads (see toyhost's docs/manifest.md); each "
           "channel spells out its `filter`, `wrap` (and `vflip` for pictures and videos): copy them from the "
           "site's settings under each iChannel, as a pixel-exact buffer (a cellular automaton) needs "
           "`\"filter\": \"nearest\"`\n\n"
           "## Inputs and controls\n\n"
           "iMouse, keys, textures: say what this shader reads and what a user can do.\n";
}

Status writeText(const fs::path& path, std::string_view text) {
    return writeBytesAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace

Result<StarterLayout> parseStarterLayout(std::string_view text) {
    StarterLayout layout;
    const std::string all = lower(trimmed(text));
    if (all == "image") return layout;
    if (all == "buffer" || all == "buffers") {
        layout.buffers[0] = true;
        return layout;
    }
    std::size_t start = 0;
    while (start <= all.size()) {
        std::size_t comma = all.find(',', start);
        if (comma == std::string::npos) comma = all.size();
        std::string word = trimmed(std::string_view(all).substr(start, comma - start));
        if (word.rfind("buffer ", 0) == 0) word = trimmed(word.substr(7));
        if (word.empty()) {  // "image," or "a,,image": nothing between the commas
        } else if (word == "common") layout.common = true;
        else if (word == "image") {
        } else if (word.size() == 1 && word[0] >= 'a' && word[0] <= 'd') layout.buffers[word[0] - 'a'] = true;
        else
            return Error("--passes: \"" + word +
                             "\" is not a pass (use image, buffers, or a comma list of common, a, b, c, d, image)",
                         Code::UsagePasses);
        start = comma + 1;
    }
    return layout;
}

ManifestDesc starterManifest(const fs::path& dir, const StarterLayout& layout) {
    ManifestDesc desc;
    const fs::path absolute = fs::absolute(dir).lexically_normal();
    desc.name = (absolute.has_filename() ? absolute : absolute.parent_path()).filename().string();
    desc.manifestPath = absolute / "manifest.json";
    if (layout.common) {
        desc.commonSource = absolute / "common.glsl";
        desc.commonName = desc.commonSource->string();
        desc.commonCode = std::string(kCommonCode);
    }
    for (int b = 0; b < kBufferCount; ++b) {
        if (!layout.buffers[b]) continue;
        PassDesc pass;
        pass.id = bufferPass(b);
        pass.source = absolute / passFileName(pass.id);
        pass.sourceName = pass.source.string();
        if (b == 0) {
            pass.code = std::string(kFeedbackBufferCode);
            pass.channels[0].kind = ChannelKind::Buffer;
            pass.channels[0].buffer = 0;
            pass.channels[0].sampler = defaultSampler(ChannelKind::Buffer);
        } else {
            pass.code = std::string(kSiteBufferCode);
        }
        desc.passes.push_back(std::move(pass));
    }
    PassDesc image;
    image.id = PassId::Image;
    image.source = absolute / passFileName(PassId::Image);
    image.sourceName = image.source.string();
    if (layout.buffers[0]) {
        image.code = std::string(kShowBufferCode);
        image.channels[0].kind = ChannelKind::Buffer;
        image.channels[0].buffer = 0;
        image.channels[0].sampler = defaultSampler(ChannelKind::Buffer);
    } else {
        image.code = std::string(kSiteImageCode);
    }
    desc.passes.push_back(std::move(image));
    return desc;
}

Status writeStarter(const fs::path& dir, const StarterLayout& layout, bool overwrite) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        return fileError(dir.string(), "exists and is not a folder", Code::IoNotAFolder);
    const ManifestDesc desc = starterManifest(dir, layout);
    // Checked before anything is written: manifest.json is JSON, which holds UTF-8 only (the
    // serializer threw here, after image.glsl was written).
    if (!isValidUtf8(desc.name))
        return fileError(dir.string(),
                         "the folder's name is not valid UTF-8, and it becomes the shadertoy's name in manifest.json "
                         "(JSON holds UTF-8 only): choose another name",
                         Code::Usage);
    fs::create_directories(dir, ec);
    if (ec) return fileError(dir.string(), "cannot create the folder: " + ec.message(), Code::IoWrite);
    if (!overwrite) {
        std::vector<fs::path> files{dir / "manifest.json", dir / "README.md"};
        if (desc.commonSource) files.push_back(dir / "common.glsl");
        for (const PassDesc& pass : desc.passes) files.push_back(dir / passFileName(pass.id));
        for (const fs::path& file : files)
            if (fs::exists(file, ec))
                return fileError(file.string(), "already exists (use --force to overwrite)", Code::IoExists);
    }
    if (Status written = writeManifestFolder(desc, dir, overwrite); !written) return written;
    return writeText(dir / "README.md", readme(desc));
}

}  // namespace toyhost
