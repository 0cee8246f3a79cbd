#include "session/Checkpoint.h"

#include "session/BackgroundWriter.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "core/AtomicFile.h"
#include "core/Defaults.h"

namespace toyhost {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {
constexpr const char* kMagic = "TOYHOST-CHECKPOINT 1";
constexpr int kMaxSide = 16384;
static_assert(std::endian::native == std::endian::little, "checkpoints store floats little-endian");

std::string hex(std::span<const std::uint8_t> bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string out;
    out.reserve(bytes.size() * 2);
    for (std::uint8_t b : bytes) {
        out += digits[b >> 4];
        out += digits[b & 15];
    }
    return out;
}

bool unhex(const std::string& text, std::span<std::uint8_t> out) {
    if (text.size() != out.size() * 2) return false;
    auto value = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        return -1;
    };
    for (std::size_t i = 0; i < out.size(); ++i) {
        const int high = value(text[2 * i]), low = value(text[2 * i + 1]);
        if (high < 0 || low < 0) return false;
        out[i] = static_cast<std::uint8_t>(high * 16 + low);
    }
    return true;
}

Error bad(const fs::path& path, const std::string& what) {
    return fileError(path.string(), "not a usable checkpoint: " + what, Code::CheckpointFormat);
}
}  // namespace

std::string codeHash(const ManifestDesc& manifest, std::span<const MacroDefine> defines) {
    // FNV-1a, 64 bits, over Common and each pass (name and code), separated.
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](std::string_view text) {
        for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
        h = (h ^ 0xff) * 1099511628211ull;
    };
    mix(manifest.commonCode);
    for (const PassDesc& pass : manifest.passes) {
        mix(passName(pass.id));
        mix(pass.code);
    }
    // Without defines the hash is the one checkpoints had before --define existed.
    for (const MacroDefine& define : defines) {
        mix("#define");
        mix(define.name);
        mix(define.value);
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
    return text;
}

std::vector<std::string> channelMedia(const ManifestDesc& manifest) {
    std::set<std::string> media;
    for (const PassDesc& pass : manifest.passes)
        for (const ChannelDesc& channel : pass.channels) {
            if (channel.kind == ChannelKind::StockMedia) media.insert(channel.media);
            if (channel.kind == ChannelKind::ImageFile) media.insert(channel.file.string());
        }
    return {media.begin(), media.end()};
}

Status writeCheckpoint(const fs::path& path, const Checkpoint& c) {
    const PlayerState& s = c.state;
    json header = {{"shadertoy", c.shadertoy},
                   {"code", c.codeHash},
                   {"media", c.media},
                   {"fps", c.fps},
                   {"start_time", c.startTime},
                   {"wall_clock", c.wallClock},
                   {"frame", s.frame},
                   {"step", s.step},
                   {"width", s.width},
                   {"height", s.height},
                   {"mouse",
                    {s.mouse.position.x, s.mouse.position.y, s.mouse.clickOrigin.x, s.mouse.clickOrigin.y, s.mouse.held,
                     s.mouse.clickedThisFrame, s.mouse.everClicked}},
                   {"keyboard", hex(s.keyboard)}};
    json buffers = json::array();
    for (const PlayerState::Buffer& b : s.buffers) buffers.push_back(std::string(1, static_cast<char>('A' + b.index)));
    header["buffers"] = buffers;
    if (s.cubeSize > 0) header["cube"] = s.cubeSize;  // Cube A's two slots follow the buffers
    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return fileError(path.string(), std::string("cannot open for writing: ") + std::strerror(errno), Code::IoWrite);
        out << kMagic << "\n" << header.dump() << "\n";
        for (const PlayerState::Buffer& b : s.buffers)
            for (const std::vector<float>& slot : b.slots)
                out.write(reinterpret_cast<const char*>(slot.data()), static_cast<std::streamsize>(slot.size() * sizeof(float)));
        if (s.cubeSize > 0)
            for (const std::vector<float>& slot : s.cube)
                out.write(reinterpret_cast<const char*>(slot.data()), static_cast<std::streamsize>(slot.size() * sizeof(float)));
        out.close();
        if (!out)
            return fileError(path.string(), std::string("write failed: ") + std::strerror(errno),
                             errno == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
        return okStatus();
    });
}

Result<Checkpoint> readCheckpoint(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        if (!fs::exists(path, ec)) return fileError(path.string(), "file not found", Code::IoNotFound);
        return fileError(path.string(), "is not a regular file", Code::IoNotAFile);
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return fileError(path.string(), std::string("cannot open: ") + std::strerror(errno), Code::IoRead);
    std::string magic, line;
    std::getline(in, magic);
    if (magic != kMagic) return bad(path, "it does not start with \"" + std::string(kMagic) + "\"");
    // The header is one line; a checkpoint's is a few hundred bytes.
    constexpr std::size_t kMaxHeader = 1 << 20;
    line.reserve(256);
    for (char ch; in.get(ch) && ch != '\n';) {
        line += ch;
        if (line.size() > kMaxHeader) return bad(path, "its header line is too long");
    }
    Checkpoint c;
    PlayerState& s = c.state;
    try {
        const json h = json::parse(line);
        c.shadertoy = h.at("shadertoy").get<std::string>();
        c.codeHash = h.at("code").get<std::string>();
        c.media = h.at("media").get<std::vector<std::string>>();
        c.fps = h.at("fps").get<double>();
        c.startTime = h.at("start_time").get<double>();
        c.wallClock = h.at("wall_clock").get<double>();
        s.frame = h.at("frame").get<int>();
        s.step = h.at("step").get<std::uint64_t>();
        s.width = h.at("width").get<int>();
        s.height = h.at("height").get<int>();
        const json& m = h.at("mouse");
        if (!m.is_array() || m.size() != 7) return bad(path, "\"mouse\" must hold 7 values");
        s.mouse.position = {m[0].get<float>(), m[1].get<float>()};
        s.mouse.clickOrigin = {m[2].get<float>(), m[3].get<float>()};
        s.mouse.held = m[4].get<bool>();
        s.mouse.clickedThisFrame = m[5].get<bool>();
        s.mouse.everClicked = m[6].get<bool>();
        if (!unhex(h.at("keyboard").get<std::string>(), s.keyboard)) return bad(path, "\"keyboard\" is not 768 bytes of hex");
        for (const json& name : h.at("buffers")) {
            const std::string letter = name.get<std::string>();
            if (letter.size() != 1 || letter[0] < 'A' || letter[0] > 'D') return bad(path, "unknown buffer " + name.dump());
            PlayerState::Buffer b;
            b.index = letter[0] - 'A';
            s.buffers.push_back(std::move(b));
        }
        s.cubeSize = h.value("cube", 0);
        if (s.cubeSize != 0 && s.cubeSize != defaults::kCubeBufferSize)
            return bad(path, "its Cube A size " + std::to_string(s.cubeSize) + " is not " +
                                 std::to_string(defaults::kCubeBufferSize));
    } catch (const json::exception& e) {
        return bad(path, std::string("its header is not valid: ") + e.what());
    }
    if (!std::isfinite(c.fps) || c.fps <= 0 || !std::isfinite(c.startTime) || !std::isfinite(c.wallClock))
        return bad(path, "its clock (fps, start time, date) is not valid");
    if (s.frame < 0 || s.width < 1 || s.height < 1 || s.width > kMaxSide || s.height > kMaxSide)
        return bad(path, "its frame or canvas size is out of range");
    const std::size_t values = static_cast<std::size_t>(s.width) * static_cast<std::size_t>(s.height) * 4;
    const std::size_t cubeValues = std::size_t(6) * s.cubeSize * s.cubeSize * 4;
    const std::uintmax_t expected = static_cast<std::uintmax_t>(in.tellg()) +
                                    (s.buffers.size() * 2 * values + 2 * cubeValues) * sizeof(float);
    if (fs::file_size(path, ec) != expected)
        return bad(path, "its size does not match its header (" + std::to_string(s.buffers.size()) + " buffers of " +
                             std::to_string(s.width) + "x" + std::to_string(s.height) + "): truncated?");
    for (PlayerState::Buffer& b : s.buffers)
        for (std::vector<float>& slot : b.slots) {
            slot.resize(values);
            if (!in.read(reinterpret_cast<char*>(slot.data()), static_cast<std::streamsize>(values * sizeof(float))))
                return bad(path, "it is truncated");
        }
    for (std::vector<float>& slot : s.cube) {
        if (cubeValues == 0) break;
        slot.resize(cubeValues);
        if (!in.read(reinterpret_cast<char*>(slot.data()), static_cast<std::streamsize>(cubeValues * sizeof(float))))
            return bad(path, "it is truncated");
    }
    return c;
}

Result<std::filesystem::path> writeCheckpointOffThread(BackgroundWriter& writer, const std::filesystem::path& path,
                                                       Checkpoint checkpoint) {
    auto shared = std::make_shared<Checkpoint>(std::move(checkpoint));
    writer.submit([path, shared]() -> Result<std::filesystem::path> {
        if (Status written = writeCheckpoint(path, *shared); !written) return written.error();
        return path;
    });
    // The next checkpoint reads the buffers again: this one is written first.
    writer.drain();
    std::optional<std::filesystem::path> last;
    for (Result<std::filesystem::path>& written : writer.takeFinished()) {
        if (!written) return written.error();
        last = *written;
    }
    if (!last) return Error("the checkpoint " + path.string() + " was not written", Code::Internal);
    return *last;
}

}  // namespace toyhost
