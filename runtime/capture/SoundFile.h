// SoundFile: the Sound pass's samples (render/SoundRenderer.h) written as an audio file, by the
// name's extension: .wav directly (16-bit PCM), .flac, .ogg, .opus, .mp3 and .m4a through ffmpeg;
// "-" is WAV on stdout. No GL needed.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "core/Result.h"

namespace toyhost {

// The extensions writeSoundFile knows, for messages: ".wav, .flac, .ogg, .opus, .mp3 or .m4a".
std::string soundFileExtensions();

// Ok when writeSoundFile can tell the format of `path`: "-", a name with one of the extensions
// above, or an existing device or FIFO (/dev/null, /dev/full: WAV unless its name has one). Else
// a usage error (Code::UsageOut) naming the accepted extensions. For checking --out before
// rendering.
Status checkSoundOutput(const std::filesystem::path& path);

// Writes `interleavedStereo` (left, right, ... at 44100 Hz) to `path`. A file is written all or
// nothing: under a temporary name beside it (registered with core/InFlight, so an emergency exit
// removes it), renamed when complete; a failure leaves no file. "-" (stdout), a device or a FIFO
// are written as they are. Errors name the file: a full disk or device says "no space left on
// device" (Code::IoNoSpace), a closed stdout "broken pipe"; never an exception.
Status writeSoundFile(const std::filesystem::path& path, std::span<const float> interleavedStereo);

}  // namespace toyhost
