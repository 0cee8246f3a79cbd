#include "media/AudioClip.h"

#include <cstring>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/InFlight.h"
#include "core/TemporaryFiles.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
constexpr int kMinSampleRate = 8000;
constexpr int kMaxSampleRate = 192000;

std::string secondsText(double seconds) {
    std::string text = std::to_string(seconds);
    text.erase(text.find_last_not_of('0') + 1);
    if (!text.empty() && text.back() == '.') text.pop_back();
    return text;
}
}  // namespace

Result<AudioClip> decodeAudioFile(const fs::path& path, int sampleRate) {
    static_assert(std::endian::native == std::endian::little, "f32le samples are read as native floats");
    const std::string name = path.string();
    if (sampleRate < kMinSampleRate || sampleRate > kMaxSampleRate)
        return fileError(name, "cannot decode audio: sample rate " + std::to_string(sampleRate) + " is not in " +
                                   std::to_string(kMinSampleRate) + ".." + std::to_string(kMaxSampleRate),
                         Code::AudioDecode);
    if (Status regular = checkRegularFile(path, "audio"); !regular) return regular.error();
    if (!findExecutable("ffmpeg"))
        return fileError(name, "cannot decode audio: ffmpeg was not found in PATH (install ffmpeg to use audio files)",
                         Code::AudioFfmpegMissing);

    TemporaryFiles temp("audio", {"f32", "log"});
    if (!temp.registerAll()) return fileError(name, "not decoded: toyhost is stopping", Code::Interrupted);
    // "file:" keeps a name such as "concat:x" or "http:x" a local file; -t one second past the
    // limit tells a file over the limit from one exactly at it without decoding all of a long one.
    std::error_code ec;
    const fs::path input = fs::absolute(path, ec);
    const std::vector<std::string> args = {
        "ffmpeg", "-nostdin", "-hide_banner", "-v", "error", "-i", "file:" + (ec ? path : input).string(),
        "-map", "0:a:0", "-vn", "-sn", "-dn", "-t", secondsText(kMaxAudioSeconds + 1.0),
        "-c:a", "pcm_f32le", "-f", "wav", "-bitexact", "-map_metadata", "-1", "-ar", std::to_string(sampleRate), "-y",
        "file:" + temp[0].string()};
    Result<ChildProcess> ffmpeg = ChildProcess::spawn(args, temp[1]);
    if (!ffmpeg) return inFile(name, ffmpeg.error());
    Result<int> exit = ffmpeg->closeAndWait();
    auto failed = [&](const std::string& what) {
        std::string message = "cannot decode audio: " + what;
        if (std::string tail = logTail(temp[1]); !tail.empty()) message += "; ffmpeg said: " + tail;
        return fileError(name, message, Code::AudioDecode);
    };
    if (!exit) return failed(exit.error().first().message);
    if (*exit != 0) return failed("ffmpeg failed (exit code " + std::to_string(*exit) + ")");

    // The file's own channels (ffmpeg's down-mix depends on whether the file declares a channel
    // layout), mixed down here as WebAudio mixes an analyser's input (speakers rules).
    Result<std::string> wav = readTextFile(temp[0], std::size_t(4) << 30);
    if (!wav) return failed("ffmpeg wrote no samples");
    const std::string& bytes = *wav;
    auto u32 = [&](std::size_t at) {
        return std::uint32_t(std::uint8_t(bytes[at])) | std::uint32_t(std::uint8_t(bytes[at + 1])) << 8 |
               std::uint32_t(std::uint8_t(bytes[at + 2])) << 16 | std::uint32_t(std::uint8_t(bytes[at + 3])) << 24;
    };
    int channels = 0;
    std::size_t dataAt = 0, dataBytes = 0;
    for (std::size_t at = 12; at + 8 <= bytes.size();) {
        const std::uint32_t size = u32(at + 4);
        if (bytes.compare(at, 4, "fmt ") == 0 && at + 12 <= bytes.size())
            channels = std::uint8_t(bytes[at + 10]) | std::uint8_t(bytes[at + 11]) << 8;
        if (bytes.compare(at, 4, "data") == 0) {
            dataAt = at + 8;
            dataBytes = std::min<std::size_t>(size, bytes.size() - dataAt);
            break;
        }
        at += 8 + size + (size & 1);
    }
    if (channels < 1 || dataAt == 0) return failed("ffmpeg's output has no audio samples");
    const std::uintmax_t count = dataBytes / sizeof(float) / static_cast<std::size_t>(channels);
    const auto limit = static_cast<std::uintmax_t>(kMaxAudioSeconds * sampleRate);
    if (count > limit)
        return fileError(name,
                         "cannot decode audio: it is longer than the " + secondsText(kMaxAudioSeconds / 60.0) +
                             " minutes toyhost reads (cut it, e.g. ffmpeg -i IN -t " + secondsText(kMaxAudioSeconds) +
                             " OUT)",
                         Code::AudioTooLong);
    if (count == 0) return failed("the file has no audio samples");

    // WebAudio's down-mix to mono: stereo (L+R)/2, quad (L+R+SL+SR)/4, 5.1
    // sqrt(1/2)(L+R) + C + 1/2(SL+SR); anything else here: the mean of the channels.
    std::vector<float> weights(static_cast<std::size_t>(channels), 1.0f / static_cast<float>(channels));
    if (channels == 6) weights = {0.70710678f, 0.70710678f, 1.0f, 0.0f, 0.5f, 0.5f};
    AudioClip clip;
    clip.sampleRate = sampleRate;
    clip.mono.resize(static_cast<std::size_t>(count));
    const char* data = bytes.data() + dataAt;
    for (std::size_t i = 0; i < clip.mono.size(); ++i) {
        float sum = 0.0f;
        for (int c = 0; c < channels; ++c) {
            float v = 0.0f;
            std::memcpy(&v, data + (i * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)) * sizeof(float),
                        sizeof(float));
            sum += weights[static_cast<std::size_t>(c)] * v;
        }
        clip.mono[i] = sum;
    }
    return clip;
}


void samplesEndingAt(const AudioClip& clip, double time, bool loop, std::span<float> out) {
    std::fill(out.begin(), out.end(), 0.0f);
    const auto size = static_cast<std::int64_t>(clip.mono.size());
    if (!std::isfinite(time) || size == 0 || clip.sampleRate <= 0) return;
    // Far past any clip's end; keeps the index arithmetic in range.
    const double position = std::clamp(time * clip.sampleRate, -1e15, 1e15);
    const auto end = static_cast<std::int64_t>(std::floor(position));
    const auto first = end - static_cast<std::int64_t>(out.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const std::int64_t index = first + static_cast<std::int64_t>(i);
        if (index < 0) continue;
        if (index < size)
            out[i] = clip.mono[static_cast<std::size_t>(index)];
        else if (loop)
            out[i] = clip.mono[static_cast<std::size_t>(index % size)];
    }
}

}  // namespace toyhost
