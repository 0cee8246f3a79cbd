#include "media/AudioAnalyser.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>

#include <fftw3.h>

namespace toyhost {

namespace {
constexpr int kMinFftSize = 2 * kAudioTextureWidth;  // row 0 needs 512 bins
constexpr int kMaxFftSize = 32768;                   // WebAudio's largest

// FFTW's planner is not thread-safe (plans may execute concurrently, but creating and destroying
// them may not): every plan of this module is made and freed under this lock.
std::mutex& plannerLock() {
    static std::mutex lock;
    return lock;
}

AnalyserSettings usable(AnalyserSettings s) {
    const AnalyserSettings defaults;
    if (s.fftSize < kMinFftSize) s.fftSize = kMinFftSize;
    if (s.fftSize > kMaxFftSize) s.fftSize = kMaxFftSize;
    s.fftSize = static_cast<int>(std::bit_ceil(static_cast<unsigned>(s.fftSize)));
    s.smoothingTimeConstant =
        std::isnan(s.smoothingTimeConstant) ? defaults.smoothingTimeConstant : std::clamp(s.smoothingTimeConstant, 0.0, 1.0);
    if (!std::isfinite(s.minDecibels) || !std::isfinite(s.maxDecibels) || !(s.minDecibels < s.maxDecibels)) {
        s.minDecibels = defaults.minDecibels;
        s.maxDecibels = defaults.maxDecibels;
    }
    return s;
}

std::uint8_t timeDomainByte(float x) {
    const double scaled = 128.0 * (1.0 + static_cast<double>(x));
    if (!(scaled > 0.0)) return 0;  // also NaN
    return static_cast<std::uint8_t>(std::min(scaled, 255.0));
}
}  // namespace

Status validateAnalyserSettings(const AnalyserSettings& s) {
    std::vector<Diagnostic> problems;
    auto problem = [&](const std::string& field, const std::string& message) {
        Diagnostic d;
        d.code = Code::AudioSettings;
        d.field = field;
        d.message = message;
        problems.push_back(std::move(d));
    };
    if (s.fftSize < kMinFftSize || s.fftSize > kMaxFftSize || !std::has_single_bit(static_cast<unsigned>(s.fftSize)))
        problem("fftSize", std::to_string(s.fftSize) + " is not a power of two in " + std::to_string(kMinFftSize) + ".." +
                               std::to_string(kMaxFftSize));
    if (!(s.smoothingTimeConstant >= 0.0 && s.smoothingTimeConstant <= 1.0))
        problem("smoothingTimeConstant", std::to_string(s.smoothingTimeConstant) + " is not in 0..1");
    if (!std::isfinite(s.minDecibels) || !std::isfinite(s.maxDecibels) || !(s.minDecibels < s.maxDecibels))
        problem("minDecibels", "the range " + std::to_string(s.minDecibels) + ".." + std::to_string(s.maxDecibels) +
                                   " dB is empty, reversed or not finite");
    if (problems.empty()) return okStatus();
    return Error(std::move(problems));
}

AudioAnalyser::AudioAnalyser(const AnalyserSettings& settings) : settings_(usable(settings)) {
    const int n = settings_.fftSize;
    window_.resize(static_cast<std::size_t>(n));
    // Computed in double, like Chromium's ApplyWindow.
    constexpr double a = 0.16, a0 = 0.5 * (1.0 - a), a1 = 0.5, a2 = 0.5 * a;
    for (int i = 0; i < n; ++i) {
        const double x = static_cast<double>(i) / n;
        window_[static_cast<std::size_t>(i)] = static_cast<float>(
            a0 - a1 * std::cos(2.0 * std::numbers::pi * x) + a2 * std::cos(4.0 * std::numbers::pi * x));
    }
    smoothed_.assign(kAudioTextureWidth, 0.0f);  // only the bins the texture shows are kept
    {
        std::lock_guard<std::mutex> lock(plannerLock());
        input_ = fftwf_alloc_real(static_cast<std::size_t>(n));
        fftwf_complex* spectrum = fftwf_alloc_complex(static_cast<std::size_t>(n / 2 + 1));
        spectrum_ = spectrum;
        // FFTW_ESTIMATE: no timing runs, so the plan (and the result's rounding) is the same on
        // every run.
        plan_ = fftwf_plan_dft_r2c_1d(n, input_, spectrum, FFTW_ESTIMATE);
    }
    reset();
}

AudioAnalyser::~AudioAnalyser() { release(); }

void AudioAnalyser::release() {
    std::lock_guard<std::mutex> lock(plannerLock());
    if (plan_) fftwf_destroy_plan(static_cast<fftwf_plan>(plan_));
    fftwf_free(input_);
    fftwf_free(spectrum_);
    plan_ = nullptr;
    input_ = nullptr;
    spectrum_ = nullptr;
}

AudioAnalyser::AudioAnalyser(AudioAnalyser&& other) noexcept
    : settings_(other.settings_),
      input_(std::exchange(other.input_, nullptr)),
      spectrum_(std::exchange(other.spectrum_, nullptr)),
      plan_(std::exchange(other.plan_, nullptr)),
      window_(std::move(other.window_)),
      smoothed_(std::move(other.smoothed_)),
      texels_(other.texels_) {}

AudioAnalyser& AudioAnalyser::operator=(AudioAnalyser&& other) noexcept {
    if (this != &other) {
        release();
        settings_ = other.settings_;
        input_ = std::exchange(other.input_, nullptr);
        spectrum_ = std::exchange(other.spectrum_, nullptr);
        plan_ = std::exchange(other.plan_, nullptr);
        window_ = std::move(other.window_);
        smoothed_ = std::move(other.smoothed_);
        texels_ = other.texels_;
    }
    return *this;
}

void AudioAnalyser::reset() {
    std::fill(smoothed_.begin(), smoothed_.end(), 0.0f);
    std::fill(texels_.begin(), texels_.begin() + kAudioTextureWidth, std::uint8_t{0});
    std::fill(texels_.begin() + kAudioTextureWidth, texels_.end(), std::uint8_t{128});
}

void AudioAnalyser::analyse(std::span<const float> lastSamples) {
    if (!plan_) return;  // moved from
    const std::size_t n = static_cast<std::size_t>(settings_.fftSize);
    if (lastSamples.size() > n) lastSamples = lastSamples.last(n);
    const std::size_t silence = n - lastSamples.size();
    auto sample = [&](std::size_t i) { return i < silence ? 0.0f : lastSamples[i - silence]; };

    // Row 1: the oldest 512 samples of the window (see the header).
    for (std::size_t i = 0; i < kAudioTextureWidth; ++i) texels_[kAudioTextureWidth + i] = timeDomainByte(sample(i));

    for (std::size_t i = 0; i < n; ++i) input_[i] = sample(i) * window_[i];
    fftwf_execute(static_cast<fftwf_plan>(plan_));
    const auto* spectrum = static_cast<const fftwf_complex*>(spectrum_);

    const double tau = settings_.smoothingTimeConstant;
    const double scale = 1.0 / static_cast<double>(n);
    const double byteScale = 255.0 / (settings_.maxDecibels - settings_.minDecibels);
    for (std::size_t k = 0; k < smoothed_.size(); ++k) {
        const double magnitude = std::hypot(static_cast<double>(spectrum[k][0]), static_cast<double>(spectrum[k][1])) * scale;
        double next = tau * smoothed_[k] + (1.0 - tau) * magnitude;
        if (!std::isfinite(next)) next = 0.0;  // a NaN or infinite input must not stick
        smoothed_[k] = static_cast<float>(next);
        const double db = 20.0 * std::log10(static_cast<double>(smoothed_[k]));  // -inf for 0
        const double scaled = byteScale * (db - settings_.minDecibels);
        texels_[k] = scaled > 0.0 ? static_cast<std::uint8_t>(std::min(scaled, 255.0)) : std::uint8_t{0};
    }
}

}  // namespace toyhost
