// AudioAnalyser and AudioClip: the 512x2 audio texture computed as WebAudio's AnalyserNode does
// (bytes predicted from the spec's formulas for bin-centred sines), decoding audio files through
// ffmpeg and the window of samples for a playback time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "TestFolder.h"
#include "core/ChildProcess.h"
#include "media/AudioAnalyser.h"
#include "media/AudioClip.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {
constexpr int kRate = 44100;

std::vector<float> sine(double frequency, double amplitude, std::size_t count, std::size_t start = 0,
                        double rate = kRate) {
    std::vector<float> x(count);
    for (std::size_t i = 0; i < count; ++i)
        x[i] = static_cast<float>(amplitude * std::sin(2.0 * std::numbers::pi * frequency *
                                                        static_cast<double>(start + i) / rate));
    return x;
}

std::vector<int> row(const AudioAnalyser& analyser, int y) {
    const auto& texels = analyser.texels();
    return std::vector<int>(texels.begin() + y * kAudioTextureWidth, texels.begin() + (y + 1) * kAudioTextureWidth);
}

int argmax(const std::vector<int>& v) { return static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin()); }

// The byte the spec's formulas give for a smoothed magnitude (defaults: -100..-30 dB).
int expectedByte(double magnitude) {
    const double db = 20.0 * std::log10(magnitude);
    return static_cast<int>(std::clamp(std::floor(255.0 / 70.0 * (db + 100.0)), 0.0, 255.0));
}

int zeroCrossings(const std::vector<float>& x) {
    int crossings = 0;
    for (std::size_t i = 1; i < x.size(); ++i)
        if ((x[i - 1] < 0.0f) != (x[i] < 0.0f)) ++crossings;
    return crossings;
}

bool haveFfmpeg() { return findExecutable("ffmpeg").has_value(); }

// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old, hadOld_ = true;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (hadOld_) ::setenv(name_, old_.c_str(), 1);
        else ::unsetenv(name_);
    }

private:
    const char* name_;
    std::string old_;
    bool hadOld_ = false;
};
}  // namespace

TEST(AudioAnalyser, DefaultsAreWebAudiosAndShowSilenceBeforeAnyAnalysis) {
    AudioAnalyser analyser;
    EXPECT_EQ(analyser.settings().fftSize, 2048);
    EXPECT_DOUBLE_EQ(analyser.settings().smoothingTimeConstant, 0.8);
    EXPECT_DOUBLE_EQ(analyser.settings().minDecibels, -100.0);
    EXPECT_DOUBLE_EQ(analyser.settings().maxDecibels, -30.0);
    EXPECT_EQ(row(analyser, 0), std::vector<int>(512, 0));
    EXPECT_EQ(row(analyser, 1), std::vector<int>(512, 128));
}

TEST(AudioAnalyser, SilenceGivesZeroSpectrumAndMidWaveform) {
    AudioAnalyser analyser;
    analyser.analyse(sine(1000.0, 0.5, 2048));
    const std::vector<float> silence(2048, 0.0f);
    for (int i = 0; i < 200; ++i) analyser.analyse(silence);  // smoothing decays below -100 dB
    EXPECT_EQ(row(analyser, 0), std::vector<int>(512, 0));
    EXPECT_EQ(row(analyser, 1), std::vector<int>(512, 128));
}

TEST(AudioAnalyser, BinCentredSinesGiveTheBytesTheSpecPredicts) {
    // A sine of amplitude A at bin k, Blackman windowed: |X[k]| = A*a0/2 = 0.21 A,
    // |X[k+-1]| = A*a1/4 = 0.125 A, |X[k+-2]| = A*a2/4 = 0.02 A, nothing further.
    const double a = 0.01;
    for (int k : {10, 100, 300, 509}) {
        AudioAnalyser analyser;
        const std::vector<float> x = sine(k * static_cast<double>(kRate) / 2048.0, a, 2048);
        for (int i = 0; i < 80; ++i) analyser.analyse(x);
        const std::vector<int> spectrum = row(analyser, 0);
        EXPECT_EQ(argmax(spectrum), k);
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k)], expectedByte(0.21 * a)) << k;  // 169
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k - 1)], expectedByte(0.125 * a)) << k;  // 152
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k + 1)], expectedByte(0.125 * a)) << k;
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k - 2)], expectedByte(0.02 * a)) << k;  // 94
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k + 2)], expectedByte(0.02 * a)) << k;
        EXPECT_EQ(spectrum[static_cast<std::size_t>(k - 3)], 0) << k;
        for (int bin = 0; bin < 512; ++bin)
            if (std::abs(bin - k) > 2) EXPECT_EQ(spectrum[static_cast<std::size_t>(bin)], 0) << k << " " << bin;
    }
    EXPECT_EQ(expectedByte(0.21 * a), 169);
}

TEST(AudioAnalyser, SmoothingFollowsTauTimesPreviousPlusTheRest) {
    const double a = 0.01;
    const std::vector<float> x = sine(100 * static_cast<double>(kRate) / 2048.0, a, 2048);
    AudioAnalyser smoothed;
    smoothed.analyse(x);
    EXPECT_EQ(row(smoothed, 0)[100], expectedByte(0.2 * 0.21 * a));  // (1 - 0.8) |X|: 118
    smoothed.analyse(x);
    EXPECT_EQ(row(smoothed, 0)[100], expectedByte(0.36 * 0.21 * a));  // 0.8*0.2 + 0.2: 136

    AudioAnalyser immediate(AnalyserSettings{.smoothingTimeConstant = 0.0});
    immediate.analyse(x);
    EXPECT_EQ(row(immediate, 0)[100], 169);

    smoothed.reset();
    EXPECT_EQ(row(smoothed, 0), std::vector<int>(512, 0));
    smoothed.analyse(x);
    EXPECT_EQ(row(smoothed, 0)[100], 118);
}

TEST(AudioAnalyser, APureToneHasItsPeakInTheNearestBin) {
    for (double f : {440.0, 1000.0, 5000.0}) {
        AudioAnalyser analyser;
        for (int i = 0; i < 60; ++i)
            analyser.analyse(sine(f, 0.01, 2048, static_cast<std::size_t>(i) * 735));  // a frame at 60 fps
        const std::vector<int> spectrum = row(analyser, 0);
        const int expected = static_cast<int>(std::lround(f * 2048.0 / kRate));
        EXPECT_EQ(argmax(spectrum), expected) << f;
        EXPECT_LT(spectrum[static_cast<std::size_t>(expected - 1)], spectrum[static_cast<std::size_t>(expected)]) << f;
        EXPECT_LT(spectrum[static_cast<std::size_t>(expected + 1)], spectrum[static_cast<std::size_t>(expected)]) << f;
        EXPECT_LT(spectrum[static_cast<std::size_t>(expected + 3)], spectrum[static_cast<std::size_t>(expected)] - 50) << f;
    }
}

TEST(AudioAnalyser, FullScaleWaveformsSpanTheWholeByteRange) {
    AudioAnalyser analyser;
    analyser.analyse(sine(1000.0, 1.0, 2048));
    const std::vector<int> wave = row(analyser, 1);
    EXPECT_LE(*std::min_element(wave.begin(), wave.end()), 1);
    EXPECT_GE(*std::max_element(wave.begin(), wave.end()), 254);
    EXPECT_EQ(wave[0], 128);  // sin(0) = 0 -> floor(128 * 1)

    std::vector<float> square(2048);
    for (std::size_t i = 0; i < square.size(); ++i) square[i] = (i / 20) % 2 ? -1.0f : 1.0f;
    analyser.analyse(square);
    const std::vector<int> squareWave = row(analyser, 1);
    EXPECT_EQ(squareWave[0], 255);   // 128 * 2 clamps
    EXPECT_EQ(squareWave[20], 0);
    EXPECT_EQ(row(analyser, 0)[2048 / 40], 255);  // the square's fundamental saturates
}

TEST(AudioAnalyser, TheWaveformRowIsTheOldest512SamplesOfTheWindow) {
    // getByteTimeDomainData fills the site's shorter array from the start of the fftSize window.
    std::vector<float> window(2048, -0.5f);
    std::fill(window.begin(), window.begin() + 512, 0.5f);
    AudioAnalyser analyser;
    analyser.analyse(window);
    EXPECT_EQ(row(analyser, 1), std::vector<int>(512, 192));  // floor(128 * 1.5)

    // A short span is the newest samples, with silence before them.
    analyser.analyse(std::vector<float>(100, 0.5f));
    EXPECT_EQ(row(analyser, 1), std::vector<int>(512, 128));
    // A longer span contributes its last fftSize samples.
    std::vector<float> longer(4096, 1.0f);
    std::fill(longer.begin() + 2048, longer.end(), -0.25f);
    analyser.analyse(longer);
    EXPECT_EQ(row(analyser, 1), std::vector<int>(512, 96));
}

TEST(AudioAnalyser, LargerFftSizesNarrowTheBins) {
    AudioAnalyser analyser(AnalyserSettings{.fftSize = 8192, .smoothingTimeConstant = 0.0});
    analyser.analyse(sine(1000.0, 0.01, 8192));
    EXPECT_EQ(argmax(row(analyser, 0)), static_cast<int>(std::lround(1000.0 * 8192 / kRate)));  // 186
}

TEST(AudioAnalyser, InvalidSettingsAreReportedAndReplaced) {
    const AnalyserSettings bad{.fftSize = 1000, .smoothingTimeConstant = 2.0, .minDecibels = -20, .maxDecibels = -30};
    Status status = validateAnalyserSettings(bad);
    ASSERT_FALSE(status.ok());
    ASSERT_EQ(status.error().diagnostics.size(), 3u) << status.error().text();
    EXPECT_EQ(status.error().diagnostics[0].field, "fftSize");
    EXPECT_EQ(status.error().diagnostics[0].code, Code::AudioSettings);
    EXPECT_EQ(status.error().diagnostics[1].field, "smoothingTimeConstant");
    EXPECT_TRUE(validateAnalyserSettings(AnalyserSettings{}).ok());

    AudioAnalyser analyser(bad);
    EXPECT_EQ(analyser.settings().fftSize, 1024);
    EXPECT_DOUBLE_EQ(analyser.settings().smoothingTimeConstant, 1.0);
    EXPECT_DOUBLE_EQ(analyser.settings().minDecibels, -100.0);
    EXPECT_DOUBLE_EQ(analyser.settings().maxDecibels, -30.0);
    EXPECT_EQ(AudioAnalyser(AnalyserSettings{.fftSize = 3000}).settings().fftSize, 4096);
    EXPECT_EQ(AudioAnalyser(AnalyserSettings{.fftSize = 1 << 20}).settings().fftSize, 32768);
}

TEST(AudioAnalyser, AMovedAnalyserKeepsWorking) {
    AudioAnalyser first(AnalyserSettings{.smoothingTimeConstant = 0.0});
    first.analyse(sine(100 * static_cast<double>(kRate) / 2048.0, 0.01, 2048));
    AudioAnalyser second(std::move(first));
    EXPECT_EQ(row(second, 0)[100], 169);
    second.analyse(sine(200 * static_cast<double>(kRate) / 2048.0, 0.01, 2048));
    EXPECT_EQ(argmax(row(second, 0)), 200);
    AudioAnalyser third;
    third = std::move(second);
    third.analyse(sine(300 * static_cast<double>(kRate) / 2048.0, 0.01, 2048));
    EXPECT_EQ(argmax(row(third, 0)), 300);
}

// ---- AudioClip -------------------------------------------------------------------------------

TEST(AudioClip, SamplesEndingAtATimeArePaddedBeforeTheStartAndWrapWhenLooping) {
    AudioClip clip;
    clip.sampleRate = 10;
    for (int i = 0; i < 10; ++i) clip.mono.push_back(static_cast<float>(i + 1));
    EXPECT_DOUBLE_EQ(clip.seconds(), 1.0);
    // Times exact in binary, so time * rate has no rounding to argue about.
    std::vector<float> out(4);
    samplesEndingAt(clip, 0.5, true, out);  // samples 1..4
    EXPECT_EQ(out, (std::vector<float>{2, 3, 4, 5}));
    samplesEndingAt(clip, 0.25, true, out);  // floor(2.5) = 2: samples -2..1
    EXPECT_EQ(out, (std::vector<float>{0, 0, 1, 2}));
    samplesEndingAt(clip, 1.25, true, out);  // samples 8..11
    EXPECT_EQ(out, (std::vector<float>{9, 10, 1, 2}));
    samplesEndingAt(clip, 1.25, false, out);
    EXPECT_EQ(out, (std::vector<float>{9, 10, 0, 0}));
    samplesEndingAt(clip, 25.5, true, out);  // samples 251..254 = 1..4 (mod 10)
    EXPECT_EQ(out, (std::vector<float>{2, 3, 4, 5}));
    samplesEndingAt(clip, -1.0, true, out);
    EXPECT_EQ(out, (std::vector<float>{0, 0, 0, 0}));
    samplesEndingAt(clip, std::nan(""), true, out);
    EXPECT_EQ(out, (std::vector<float>{0, 0, 0, 0}));
}

TEST(AudioClip, DecodesAWavFileThroughFfmpeg) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    const fs::path wav = folder.path / "tone.wav";
    const std::string command = "ffmpeg -nostdin -v error -f lavfi -i sine=frequency=1000:duration=1 -y '" +
                                wav.string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    Result<AudioClip> clip = decodeAudioFile(wav);
    ASSERT_TRUE(clip.ok()) << clip.error().text();
    EXPECT_EQ(clip->sampleRate, 44100);
    EXPECT_EQ(clip->mono.size(), 44100u);
    EXPECT_NEAR(clip->seconds(), 1.0, 1e-9);
    EXPECT_NEAR(zeroCrossings(clip->mono), 2000, 3);
    const float peak = *std::max_element(clip->mono.begin(), clip->mono.end());
    EXPECT_NEAR(peak, 0.125f, 0.01f);  // lavfi's sine is at 1/8

    Result<AudioClip> resampled = decodeAudioFile(wav, 48000);
    ASSERT_TRUE(resampled.ok()) << resampled.error().text();
    EXPECT_NEAR(static_cast<double>(resampled->mono.size()), 48000.0, 64.0);
    EXPECT_NEAR(zeroCrossings(resampled->mono), 2000, 3);
    EXPECT_EQ(folder.files(), std::vector<std::string>{"tone.wav"});
}

TEST(AudioClip, DecodingErrorsSayWhatWentWrong) {
    TestFolder folder;
    Result<AudioClip> missing = decodeAudioFile(folder.path / "missing.ogg");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().text().find("missing.ogg"), std::string::npos) << missing.error().text();

    Result<AudioClip> badRate = decodeAudioFile(folder.write("x.wav", "x"), 100);
    ASSERT_FALSE(badRate.ok());
    EXPECT_EQ(badRate.error().first().code, Code::AudioDecode);

    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    const fs::path text = folder.write("notes.mp3", "these are not the samples you are looking for\n");
    Result<AudioClip> notAudio = decodeAudioFile(text);
    ASSERT_FALSE(notAudio.ok());
    EXPECT_EQ(notAudio.error().first().code, Code::AudioDecode);
    EXPECT_EQ(notAudio.error().first().file, text.string());
    EXPECT_NE(notAudio.error().text().find("ffmpeg"), std::string::npos) << notAudio.error().text();
}

TEST(AudioClip, AMissingFfmpegIsAClearError) {
    TestFolder folder;
    const fs::path wav = folder.write("tone.wav", "RIFF");
    const fs::path emptyBin = folder.path / "bin";
    fs::create_directories(emptyBin);
    ScopedEnv path("PATH", emptyBin.string());
    Result<AudioClip> clip = decodeAudioFile(wav);
    ASSERT_FALSE(clip.ok());
    EXPECT_EQ(clip.error().first().code, Code::AudioFfmpegMissing);
    EXPECT_NE(clip.error().text().find("ffmpeg was not found"), std::string::npos) << clip.error().text();
}
