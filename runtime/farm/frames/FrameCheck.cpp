// FrameCheck: decodes each frame with image/PngDecode or image/ImageWriters' readExr (see
// FrameCheck.h). No GL needed.
#include "farm/frames/FrameCheck.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <vector>

#include "core/AtomicFile.h"
#include "core/ByteText.h"
#include "image/ImageWriters.h"
#include "image/PngDecode.h"

namespace toyhost {

namespace fs = std::filesystem;

namespace {

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

// Frames larger than this are checked from their first and last bytes only (signature, header,
// the PNG's IEND chunk), not read whole and decoded: a multi-GB file in a frame folder (a stray, a
// sparse file) made `farm status` read it all and then run out of memory.
constexpr std::uintmax_t kDecodeLimitBytes = std::uintmax_t(256) << 20;

bool readAll(const fs::path& file, std::vector<unsigned char>& bytes) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), {});
    return !in.bad();
}

// `count` bytes of `file` from `offset` (fewer at its end); false when it cannot be read.
bool readPart(const fs::path& file, std::uintmax_t offset, std::size_t count, std::vector<unsigned char>& bytes) {
    std::ifstream in(file, std::ios::binary);
    if (!in || !in.seekg(static_cast<std::streamoff>(offset))) return false;
    bytes.resize(count);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(count));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
    return !in.bad();
}

// A frame too large to decode here: its format's signature and (PNG) its IEND end, read alone.
farm::FrameState checkLargeFrame(const fs::path& file, std::uintmax_t size, std::string& reason) {
    static const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const unsigned char exr[4] = {0x76, 0x2F, 0x31, 0x01};
    std::vector<unsigned char> head, tail;
    if (!readPart(file, 0, 8, head) || !readPart(file, size - 12, 12, tail)) {
        reason = std::string("cannot be read: ") + std::strerror(errno);
        return farm::FrameState::Undecodable;
    }
    const bool isExr = file.extension() == ".exr";
    const bool signed_ = isExr ? head.size() >= 4 && std::memcmp(head.data(), exr, 4) == 0
                               : head.size() == 8 && std::memcmp(head.data(), png, 8) == 0;
    if (!signed_) {
        reason = std::string("not ") + (isExr ? "an OpenEXR" : "a PNG") + " file (" + formatBytes(size) +
                 ", too large to decode here: its first bytes were checked)";
        return farm::FrameState::Undecodable;
    }
    if (!isExr && !endsWithIend(tail)) {
        reason = "no IEND chunk at its end";
        return farm::FrameState::Truncated;
    }
    return farm::FrameState::Ok;
}

}  // namespace

farm::FrameState checkFrameFile(const fs::path& file, std::string& reason) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return farm::FrameState::Missing;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (!ec && size > kDecodeLimitBytes) return checkLargeFrame(file, size, reason);
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
        // GNU parallel's log holds a line per attempt; one far over that is not its log.
        Result<std::string> joblog = readTextFile(layout.joblog);
        if (joblog) joblogCodes = farm::exitCodesFromJoblog(*joblog);
    }
    // The folder is listed once, and only the frames found are read: a run of 2^31 frames with 8
    // on disk costs 8 checks, not 2^31 look-ups; what is absent is counted, in runs.
    std::set<int> present;
    std::error_code ec;
    for (fs::directory_iterator it(layout.frameDir, ec), end; !ec && it != end; it.increment(ec))
        if (std::optional<int> frame = layout.frameNumberOf(it->path().filename().string())) present.insert(*frame);
    for (int i = 0; i < layout.shards; ++i) {
        farm::ShardStatus shard;
        shard.index = i;
        Result<FrameSpan> span = shardSpan(layout.frames, layout.shards, i);
        if (!span) break;  // layouts are checked when made (layoutFromPlan, farm status's options)
        shard.span = *span;
        shard.expected = layout.capturedCount(span->first, span->end - 1, *span);
        // The frames absent from `from` to `to` (inclusive), as one run of those the shard writes.
        auto missing = [&](int from, int to) {
            const long long count = layout.capturedCount(from, to, shard.span);
            if (count == 0) return;
            const int first = *layout.firstCaptured(from, to, shard.span), last = *layout.lastCaptured(from, to, shard.span);
            shard.problems.push_back({first, farm::FrameState::Missing, "", last == first ? -1 : last, count});
        };
        int next = span->first;  // the first frame not yet accounted for
        for (auto it = present.lower_bound(span->first); it != present.end() && *it < span->end; ++it) {
            const int frame = *it;
            if (!layout.captured(frame, shard.span)) continue;
            missing(next, frame - 1);
            next = frame + 1;
            std::string reason;
            const farm::FrameState state = checkFrameFile(layout.frameFile(frame), reason);
            if (state == farm::FrameState::Ok)
                ++shard.good;
            else
                shard.problems.push_back({frame, state, reason});
        }
        missing(next, span->end - 1);
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
