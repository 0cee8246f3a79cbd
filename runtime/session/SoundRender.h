// SoundRender: renders a shadertoy's Sound pass (mainSound) as the site does, once and up front:
// blocks of 512x512 samples drawn into an RGBA8 target (two 16-bit values per pixel, see
// capture/SoundEncoding.h), read back and decoded to stereo floats at 44100 Hz; and writes them
// as a WAV file (or through ffmpeg as FLAC, Ogg/Opus, MP3, ... by the extension). Needs a GL
// context (it makes one headless when given none).
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "core/Result.h"
#include "gl/GlContext.h"
#include "player/PlayerDesc.h"

namespace toyhost {

struct SoundRenderDesc {
    double seconds = 0;  // 0: the site's 180 s (core/Defaults.h)
};

// Interleaved stereo samples (left, right, ...) of the plan's Sound pass, seconds * 44100 pairs.
// The Sound pass may read images, cubemaps and volumes; any other channel is an error naming it.
Result<std::vector<float>> renderSound(GlContext& context, const PlayerPlan& plan, const SoundRenderDesc& desc);

// Writes `stereo` (44100 Hz) to `path`: a .wav is written directly (16-bit PCM), another
// extension goes through ffmpeg (flac, ogg, opus, mp3, m4a, ...). All or nothing: a failure
// leaves no file.
Status writeSoundFile(const std::filesystem::path& path, const std::vector<float>& stereo);

}  // namespace toyhost
