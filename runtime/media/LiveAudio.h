// LiveAudio: a live audio input for `mic` channels: a microphone through ALSA or PulseAudio, or a
// synthetic live source (an ffmpeg lavfi graph, paced in real time), decoded by an ffmpeg child
// to mono float samples at 44100 Hz and kept in a ring by a reader thread; the render thread takes
// the newest samples each frame for the analyser (media/AudioAnalyser.h). No GL needed.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "core/ChildProcess.h"
#include "core/Defaults.h"
#include "core/Result.h"
#include "core/TemporaryFiles.h"

namespace toyhost {

class LiveAudio {
public:
    // "alsa:DEVICE" (alsa:default, alsa:hw:0), "pulse:DEVICE" or "lavfi:GRAPH" (e.g.
    // lavfi:sine=frequency=440); anything else is a file, not a live source.
    static bool isLiveSource(const std::string& spec);
    // Starts ffmpeg and waits (up to 5 s) for the first samples; an error names the source and
    // says what ffmpeg said when it could not open it.
    static Result<std::unique_ptr<LiveAudio>> open(const std::string& spec, int sampleRate = static_cast<int>(defaults::kSampleRate));
    ~LiveAudio();
    LiveAudio(const LiveAudio&) = delete;
    LiveAudio& operator=(const LiveAudio&) = delete;

    // Fills `out` with the newest samples, oldest first (zeros where none have arrived yet).
    // Returns how many samples have arrived in all. Never waits for the reader.
    std::uint64_t latest(std::span<float> out) const;

private:
    LiveAudio(ChildProcess child, std::unique_ptr<TemporaryFiles> log, std::string spec);
    void readLoop();

    ChildProcess child_;
    std::unique_ptr<TemporaryFiles> log_;
    std::string spec_;
    mutable std::mutex mutex_;
    std::condition_variable arrived_;
    std::vector<float> ring_;  // a power of two
    std::uint64_t written_ = 0;
    bool ended_ = false;
    std::thread reader_;
};

}  // namespace toyhost
