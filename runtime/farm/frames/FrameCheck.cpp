// FrameCheck: decodes each frame with image/PngDecode or image/ImageWriters' readExr (see
// FrameCheck.h). No GL needed.
#include "farm/frames/FrameCheck.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <vector>

#include "image/ImageWriters.h"
#include "image/PngDecode.h"

namespace toyhost {

namespace fs = std::filesystem;

namespace {

bool readAll(const fs::path& file, std::vector<unsigned char>& bytes) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), {});
    return !in.bad();
}

// A complete PNG ends with the IEND chunk: length 0, "IEND", its CRC AE 42 60 82.
bool endsWithIend(const std::vector<unsigned char>& bytes) {
    static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
    return bytes.size() >= 8 + 12 && std::memcmp(bytes.data() + bytes.size() - 12, iend, 12) == 0;
}

bool mentionsEarlyEnd(const std::string& text) {
    for (const char* words : {"end of file", "End of file", "truncated", "Truncated", "Early end", "early end",
                              "Unexpected end", "unexpected end", "not enough data", "Not enough data"})
        if (text.find(words) != std::string::npos) return true;
    return false;
}

}  // namespace

farm::FrameState checkFrameFile(const fs::path& file, std::string& reason) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return farm::FrameState::Missing;
    std::vector<unsigned char> bytes;
    if (!readAll(file, bytes)) {
        reason = std::string("cannot be read: ") + std::strerror(errno);
        return farm::FrameState::Undecodable;
    }
    if (bytes.empty()) {
        reason = "empty file";
        return farm::FrameState::Truncated;
    }
    if (file.extension() == ".exr") {
        Result<ImageF32> image = readExr(file);
        if (image) return farm::FrameState::Ok;
        reason = image.error().first().message;
        return mentionsEarlyEnd(reason) ? farm::FrameState::Truncated : farm::FrameState::Undecodable;
    }
    Result<Image8> image = decodePng(bytes, DecodeLimits{}, file.string());
    if (!endsWithIend(bytes)) {
        reason = image ? "no IEND chunk at its end" : image.error().first().message;
        return farm::FrameState::Truncated;
    }
    if (image) return farm::FrameState::Ok;
    reason = image.error().first().message;
    return farm::FrameState::Undecodable;
}

farm::FarmStatus checkFarm(const farm::FrameLayout& layout) {
    farm::FarmStatus status;
    std::map<int, int> joblogCodes;
    if (!layout.joblog.empty()) {
        std::ifstream in(layout.joblog);
        if (in) joblogCodes = farm::exitCodesFromJoblog(std::string((std::istreambuf_iterator<char>(in)), {}));
    }
    for (int i = 0; i < layout.shards; ++i) {
        farm::ShardStatus shard;
        shard.index = i;
        Result<FrameSpan> span = shardSpan(layout.frames, layout.shards, i);
        if (!span) break;  // layouts are checked when made (layoutFromPlan, farm status's options)
        shard.span = *span;
        for (int frame = shard.span.first; frame < shard.span.end; ++frame) {
            if (!layout.captured(frame, shard.span)) continue;
            std::string reason;
            const farm::FrameState state = checkFrameFile(layout.frameFile(frame), reason);
            if (state == farm::FrameState::Ok)
                ++shard.good;
            else
                shard.problems.push_back({frame, state, reason});
        }
        if (!layout.exitDir.empty()) {
            std::ifstream in(layout.exitDir / ("shard-" + std::to_string(i)));
            int code = 0;
            if (in >> code) shard.exitCode = code;
        }
        if (!shard.exitCode)
            if (auto found = joblogCodes.find(i); found != joblogCodes.end()) shard.exitCode = found->second;
        status.shards.push_back(std::move(shard));
    }
    return status;
}

}  // namespace toyhost
