#include "media/VolumeFile.h"

#include <algorithm>
#include <new>
#include <string>

#include "core/AtomicFile.h"
#include "image/PixelMemory.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
std::uint32_t readU32(const std::string& data, std::size_t at) {
    auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(data[at + i])); };
    return byte(0) | (byte(1) << 8) | (byte(2) << 16) | (byte(3) << 24);
}

void putU32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

std::uint64_t mix64(std::uint64_t z) {  // the splitmix64 finaliser
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}
}  // namespace

Result<Volume8> readVolumeFile(const fs::path& path) {
    const std::string name = path.string();
    auto bad = [&](const std::string& message) { return fileError(name, "cannot read volume: " + message, Code::VolumeDecode); };
    if (Status regular = checkRegularFile(path, "volume"); !regular) return regular.error();
    Result<std::string> bytes = Error("unread");
    try {
        bytes = readTextFile(path, kMaxVolumeBytes + kVolumeHeaderBytes);
    } catch (const std::bad_alloc&) {
        std::error_code ec;
        return notEnoughMemory(name, "reading the volume", formatBytes(fs::file_size(path, ec)));
    }
    if (!bytes) return bytes.error();
    const std::string& data = *bytes;
    if (data.size() < kVolumeHeaderBytes)
        return bad("the file is " + std::to_string(data.size()) + " bytes, shorter than the " +
                   std::to_string(kVolumeHeaderBytes) + "-byte header");

    const std::uint32_t sizes[3] = {readU32(data, 4), readU32(data, 8), readU32(data, 12)};
    const unsigned channels = static_cast<unsigned char>(data[16]);
    const unsigned format = static_cast<unsigned>(static_cast<unsigned char>(data[18])) |
                            (static_cast<unsigned>(static_cast<unsigned char>(data[19])) << 8);
    const std::string declared =
        std::to_string(sizes[0]) + "x" + std::to_string(sizes[1]) + "x" + std::to_string(sizes[2]);
    for (std::uint32_t side : sizes) {
        if (side == 0) return bad("the header declares a size of " + declared + " (a side is 0)");
        if (side > static_cast<std::uint32_t>(kMaxVolumeSide))
            return bad("the header declares a size of " + declared + ", larger than the " +
                       std::to_string(kMaxVolumeSide) + " a side volumes may have");
    }
    if (channels < 1 || channels > 4)
        return bad("the header declares " + std::to_string(channels) + " channels (1 to 4 are valid)");
    if (format != 0 && format != 10)
        return bad("unknown voxel format " + std::to_string(format) + " (0 is 8-bit, 10 is 32-bit float)");
    const std::uint64_t bytesPerValue = format == 10 ? 4 : 1;
    const std::uint64_t expected = std::uint64_t(sizes[0]) * sizes[1] * sizes[2] * channels * bytesPerValue;
    if (expected > kMaxVolumeBytes)
        return bad("the header declares " + declared + " x " + std::to_string(channels) + " channels = " +
                   std::to_string(expected) + " bytes, more than the limit of " + std::to_string(kMaxVolumeBytes));
    const std::uint64_t present = data.size() - kVolumeHeaderBytes;
    if (present != expected)
        return bad("the header declares " + declared + " x " + std::to_string(channels) + " channels = " +
                   std::to_string(expected) + " bytes of voxels, but the file has " + std::to_string(present) +
                   (present < expected ? " (truncated)" : " (trailing data)"));

    Volume8 volume;
    volume.width = static_cast<int>(sizes[0]);
    volume.height = static_cast<int>(sizes[1]);
    volume.depth = static_cast<int>(sizes[2]);
    volume.channels = static_cast<int>(channels);
    volume.floats = format == 10;
    if (!tryResize(volume.voxels, data.size() - kVolumeHeaderBytes))
        return notEnoughMemory(name, "the volume's voxels", formatBytes(data.size() - kVolumeHeaderBytes) + " (" + declared + ")");
    std::copy(data.begin() + kVolumeHeaderBytes, data.end(), reinterpret_cast<char*>(volume.voxels.data()));
    return volume;
}

std::vector<std::uint8_t> encodeVolumeFile(const Volume8& volume) {
    std::vector<std::uint8_t> out;
    out.reserve(kVolumeHeaderBytes + volume.voxels.size());
    putU32(out, 0);  // signature: the site never checks it
    putU32(out, static_cast<std::uint32_t>(volume.width));
    putU32(out, static_cast<std::uint32_t>(volume.height));
    putU32(out, static_cast<std::uint32_t>(volume.depth));
    out.push_back(static_cast<std::uint8_t>(volume.channels));
    out.push_back(0);  // layout
    out.push_back(volume.floats ? 10 : 0);  // format: 8-bit or 32-bit float
    out.push_back(0);
    out.insert(out.end(), volume.voxels.begin(), volume.voxels.end());
    return out;
}

Volume8 volumeStandIn(int side, int channels, std::uint32_t seed) {
    Volume8 volume;
    volume.channels = std::clamp(channels, 1, 4);
    side = std::clamp(side, 1, kMaxVolumeSide);
    while (std::uint64_t(side) * side * side * volume.channels > kMaxVolumeBytes) --side;
    volume.width = volume.height = volume.depth = side;
    volume.voxels.resize(std::size_t(side) * side * side * volume.channels);
    std::uint64_t state = mix64(0x766f6c756d65ULL ^ seed);  // "volume"
    for (std::size_t i = 0; i < volume.voxels.size(); i += 8) {
        std::uint64_t word = mix64(state += 0x9e3779b97f4a7c15ULL);
        for (std::size_t k = i; k < std::min(i + 8, volume.voxels.size()); ++k, word >>= 8)
            volume.voxels[k] = static_cast<std::uint8_t>(word);
    }
    return volume;
}

}  // namespace toyhost
