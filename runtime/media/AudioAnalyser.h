// AudioAnalyser: the 512x2 single-channel 8-bit texture Shadertoy gives `music`, `musicstream`
// and `mic` channels, computed on the CPU the way WebAudio's AnalyserNode does. No GL needed.
//
// What the site does (effect.js, EffectPass.NewTexture and Paint_Image, read in several public
// mirrors of effect.js from 2015 to the WebGL2 player): it creates the analyser with
// `wa.createAnalyser()` and changes none of its settings, so WebAudio's defaults apply:
// fftSize 2048 (1024 bins), smoothingTimeConstant 0.8, minDecibels -100, maxDecibels -30. (Not
// "fftSize 1024": the texture is 512 wide because the site uploads only the first 512 entries.)
// Each frame it calls getByteFrequencyData and getByteTimeDomainData, then uploads 512 bytes of
// each: row 0 = frequency bins 0..511 of 1024 (0 Hz up to a quarter of the sample rate), row 1 =
// the FIRST 512 time-domain bytes. getByteTimeDomainData writes the window's oldest samples
// first (its array is shorter than fftSize: 1024 entries for music, 512 for mic), so row 1 is
// the oldest 512 of the last 2048 samples, not the newest. The texture is LUMINANCE 512x2,
// linear filter, clamp.
//
// The AnalyserNode algorithm (Web Audio API spec, "FFT windowing and smoothing over time";
// checked against Chromium's realtime_analyser.cc and fft_frame_pffft.cc):
//   Blackman window, a = 0.16: w[n] = 0.42 - 0.5 cos(2 pi n/N) + 0.08 cos(4 pi n/N), n = 0..N-1
//   X[k] = |sum x[n] w[n] e^(-2 pi i k n/N)| / N               (k = 0..N/2-1, N = fftSize)
//   S[k] = tau S_prev[k] + (1 - tau) X[k]                       (smoothing, once per analysis)
//   byte = clamp(floor(255 / (maxDb - minDb) * (20 log10 S[k] - minDb)), 0, 255)
//   time-domain byte = clamp(floor(128 * (1 + x)), 0, 255)       (128 = silence)
// A bin-centred sine of amplitude A gives X[k] = 0.21 A (tests/io/test_audio_analyser.cpp checks
// the bytes this predicts).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/Result.h"

namespace toyhost {

inline constexpr int kAudioTextureWidth = 512;
inline constexpr int kAudioTextureHeight = 2;

// The analyser's settings; the member defaults are WebAudio's, which the site keeps.
struct AnalyserSettings {
    int fftSize = 2048;                   // a power of two, 1024..32768 (at least 512 bins)
    double smoothingTimeConstant = 0.8;   // 0..1
    double minDecibels = -100.0;          // maps to byte 0
    double maxDecibels = -30.0;           // maps to byte 255; greater than minDecibels
};

// Ok, or an error (Code::AudioSettings) listing every invalid field.
Status validateAnalyserSettings(const AnalyserSettings& settings);

class AudioAnalyser {
public:
    // Invalid settings are replaced by the nearest valid ones (fftSize rounded to a power of two
    // in range, smoothing clamped to 0..1, a decibel range that is empty or reversed by the
    // defaults); validateAnalyserSettings() reports them first when they come from a user.
    // Creates the FFT plan and every buffer here: analyse() allocates nothing.
    explicit AudioAnalyser(const AnalyserSettings& settings = {});
    ~AudioAnalyser();
    AudioAnalyser(AudioAnalyser&& other) noexcept;
    AudioAnalyser& operator=(AudioAnalyser&& other) noexcept;
    AudioAnalyser(const AudioAnalyser&) = delete;
    AudioAnalyser& operator=(const AudioAnalyser&) = delete;

    const AnalyserSettings& settings() const { return settings_; }

    // One analysis, as one frame's getByteFrequencyData + getByteTimeDomainData: `lastSamples`
    // are the fftSize most recent mono samples, oldest first. A shorter span is taken as the
    // newest samples with silence before them; a longer one contributes its last fftSize.
    void analyse(std::span<const float> lastSamples);

    // Forgets the smoothing history and shows silence (row 0 all 0, row 1 all 128), as a new
    // analyser would: for a restart or a seek.
    void reset();

    // 512x2 bytes, row 0 (frequency) first, then row 1 (waveform): ready for a LUMINANCE/R8
    // upload with row 0 at texel y = 0.
    const std::array<std::uint8_t, kAudioTextureWidth * kAudioTextureHeight>& texels() const { return texels_; }

private:
    void release();

    AnalyserSettings settings_;
    float* input_ = nullptr;     // fftSize windowed samples (fftwf_alloc_real)
    void* spectrum_ = nullptr;   // fftSize/2 + 1 complex values (fftwf_alloc_complex)
    void* plan_ = nullptr;       // fftwf_plan, created once
    std::vector<float> window_;  // Blackman window, fftSize values
    std::vector<float> smoothed_;  // S[k] of the previous analysis, for the 512 bins shown
    std::array<std::uint8_t, kAudioTextureWidth * kAudioTextureHeight> texels_{};
};

}  // namespace toyhost
