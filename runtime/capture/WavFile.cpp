#include "capture/WavFile.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/AtomicFile.h"

namespace toyhost {

namespace {
constexpr int kChannels = 2;
constexpr int kBytesPerSample = 2;
constexpr std::size_t kBytesPerFrame = kChannels * kBytesPerSample;
// The RIFF size field (file size - 8) is 32 bits.
constexpr std::uint64_t kMaxDataBytes = (0xFFFFFFFFull - (kWavHeaderBytes - 8)) / kBytesPerFrame * kBytesPerFrame;
constexpr int kMaxSampleRate = 768000;

void putU16(std::vector<std::uint8_t>& out, std::uint32_t value) {
    out.push_back(static_cast<std::uint8_t>(value));
    out.push_back(static_cast<std::uint8_t>(value >> 8));
}
void putU32(std::vector<std::uint8_t>& out, std::uint32_t value) {
    putU16(out, value & 0xFFFF);
    putU16(out, value >> 16);
}
void putTag(std::vector<std::uint8_t>& out, const char (&tag)[5]) { out.insert(out.end(), tag, tag + 4); }

std::int16_t toPcm16(float x) {
    if (std::isnan(x)) return 0;
    return static_cast<std::int16_t>(std::lround(std::clamp(x, -1.0f, 1.0f) * 32767.0f));
}
}  // namespace

std::vector<std::uint8_t> encodeWav16(std::span<const float> interleavedStereo, int sampleRate) {
    const std::uint64_t frames =
        std::min<std::uint64_t>(interleavedStereo.size() / kChannels, kMaxDataBytes / kBytesPerFrame);
    const auto dataBytes = static_cast<std::uint32_t>(frames * kBytesPerFrame);
    const auto rate = static_cast<std::uint32_t>(std::max(sampleRate, 0));

    std::vector<std::uint8_t> out;
    out.reserve(kWavHeaderBytes + dataBytes);
    putTag(out, "RIFF");
    putU32(out, static_cast<std::uint32_t>(kWavHeaderBytes - 8) + dataBytes);
    putTag(out, "WAVE");
    putTag(out, "fmt ");
    putU32(out, 16);  // fmt chunk size for PCM
    putU16(out, 1);   // WAVE_FORMAT_PCM
    putU16(out, kChannels);
    putU32(out, rate);
    putU32(out, rate * static_cast<std::uint32_t>(kBytesPerFrame));  // byte rate
    putU16(out, static_cast<std::uint32_t>(kBytesPerFrame));          // block align
    putU16(out, kBytesPerSample * 8);                                 // bits per sample
    putTag(out, "data");
    putU32(out, dataBytes);
    for (std::size_t i = 0; i < frames * kChannels; ++i)
        putU16(out, static_cast<std::uint16_t>(toPcm16(interleavedStereo[i])));
    return out;
}

Status writeWav16(const std::filesystem::path& path, std::span<const float> interleavedStereo, int sampleRate) {
    const std::string name = path.string();
    if (sampleRate < 1 || sampleRate > kMaxSampleRate)
        return fileError(name, "cannot write WAV: sample rate " + std::to_string(sampleRate) + " is not in 1.." +
                                   std::to_string(kMaxSampleRate), Code::CaptureWav);
    if (interleavedStereo.size() % kChannels != 0)
        return fileError(name, "cannot write WAV: " + std::to_string(interleavedStereo.size()) +
                                   " values are not whole left/right pairs", Code::CaptureWav);
    if (interleavedStereo.size() / kChannels > kMaxDataBytes / kBytesPerFrame)
        return fileError(name, "cannot write WAV: " + std::to_string(interleavedStereo.size() / kChannels) +
                                   " frames are more than a WAV file can hold", Code::CaptureWav);
    const std::vector<std::uint8_t> bytes = encodeWav16(interleavedStereo, sampleRate);
    return writeBytesAtomically(path, std::as_bytes(std::span(bytes)));
}

}  // namespace toyhost
