// AudioClip: the mono samples behind a `music` / `musicstream` / `mic` channel: decoding an audio
// file through ffmpeg (mixed down to mono as WebAudio does), and the window
// of samples an AudioAnalyser looks at for a given playback time. No GL needed.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "core/Defaults.h"
#include "core/Result.h"

namespace toyhost {

inline constexpr double kMaxAudioSeconds = 30.0 * 60.0;

struct AudioClip {
    int sampleRate = static_cast<int>(defaults::kSampleRate);
    std::vector<float> mono;  // -1..1, down-mixed to one channel
    double seconds() const { return sampleRate > 0 ? static_cast<double>(mono.size()) / sampleRate : 0.0; }
};

// Decodes any audio file ffmpeg reads (the first audio stream, also of a video file) to mono
// float at `sampleRate` (8000..192000), by running
// `ffmpeg -v error -i FILE -f f32le -ac 1 -ar RATE` with its output in a temporary file (removed
// afterwards, and by an emergency exit). ffmpeg's stereo-to-mono mix is (L+R)/2, the down-mix
// WebAudio's AnalyserNode applies. Errors: Code::AudioFfmpegMissing when ffmpeg is not in PATH,
// Code::AudioDecode when ffmpeg fails (with the last lines it printed) or finds no samples,
// Code::AudioTooLong past kMaxAudioSeconds, the I/O error for a missing file or a folder.
Result<AudioClip> decodeAudioFile(const std::filesystem::path& path, int sampleRate = static_cast<int>(defaults::kSampleRate));


// The out.size() samples that end at playback time `time` (seconds): sample index
// floor(time * rate) is the first not yet played. Indices before 0 are silence; past the end
// the clip wraps when `loop` is set (the site plays music with loop = true) and is silence
// otherwise. A non-finite time gives silence.
void samplesEndingAt(const AudioClip& clip, double time, bool loop, std::span<float> out);

}  // namespace toyhost
