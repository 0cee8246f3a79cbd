// WavFile: the Sound pass's output as a canonical RIFF/WAVE file, PCM 16-bit stereo (44-byte
// header: RIFF, fmt chunk of 16 bytes, data chunk). No GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "core/Result.h"

namespace toyhost {

inline constexpr std::size_t kWavHeaderBytes = 44;

// The file's bytes: `interleavedStereo` holds left/right pairs; each value is clamped to
// [-1, 1] and becomes round(x * 32767) (NaN becomes 0). A trailing unpaired value is ignored, and
// so are frames past the most a RIFF file's 32-bit sizes can describe.
std::vector<std::uint8_t> encodeWav16(std::span<const float> interleavedStereo, int sampleRate);

// Writes encodeWav16's bytes to `path` atomically (complete or absent). Errors (Code::CaptureWav):
// a sample rate not in 1..768000, an odd number of values, more audio than a WAV file can hold;
// and the I/O errors of writing.
Status writeWav16(const std::filesystem::path& path, std::span<const float> interleavedStereo, int sampleRate);

}  // namespace toyhost
