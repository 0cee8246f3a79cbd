// WavFile and SoundEncoding: the Sound pass's output as a 16-bit stereo WAV (header parsed back
// byte by byte) and the site's 16-bit sample encoding through RGBA8 (what the player decodes
// for chosen values, including x = 1.0, which the site stores as 65280).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <numbers>
#include <string>
#include <vector>

#include "TestFolder.h"
#include "capture/SoundEncoding.h"
#include "capture/WavFile.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {
std::uint32_t u32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return std::uint32_t(b[at]) | std::uint32_t(b[at + 1]) << 8 | std::uint32_t(b[at + 2]) << 16 |
           std::uint32_t(b[at + 3]) << 24;
}
std::uint16_t u16(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint16_t>(b[at] | b[at + 1] << 8);
}
std::string tag(const std::vector<std::uint8_t>& b, std::size_t at) { return std::string(b.begin() + at, b.begin() + at + 4); }
std::int16_t pcm(const std::vector<std::uint8_t>& b, std::size_t frame, int channel) {
    return static_cast<std::int16_t>(u16(b, kWavHeaderBytes + frame * 4 + static_cast<std::size_t>(channel) * 2));
}

std::vector<std::uint8_t> readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::vector<float> stereoSine(double frequency, double seconds, int rate, float amplitude) {
    const auto frames = static_cast<std::size_t>(seconds * rate);
    std::vector<float> samples(frames * 2);
    for (std::size_t i = 0; i < frames; ++i) {
        const double phase = 2.0 * std::numbers::pi * frequency * static_cast<double>(i) / rate;
        samples[2 * i] = amplitude * static_cast<float>(std::sin(phase));
        samples[2 * i + 1] = amplitude * static_cast<float>(std::cos(phase));
    }
    return samples;
}
}  // namespace

TEST(WavFile, HeaderIsCanonicalPcm16Stereo) {
    const std::vector<float> samples = {0.0f, 1.0f, -1.0f, 0.5f, 2.0f, -3.0f};  // 3 frames
    const std::vector<std::uint8_t> wav = encodeWav16(samples, 44100);
    ASSERT_EQ(wav.size(), 44u + 12u);
    EXPECT_EQ(tag(wav, 0), "RIFF");
    EXPECT_EQ(u32(wav, 4), wav.size() - 8);  // RIFF size: everything after this field
    EXPECT_EQ(tag(wav, 8), "WAVE");
    EXPECT_EQ(tag(wav, 12), "fmt ");
    EXPECT_EQ(u32(wav, 16), 16u);      // fmt chunk size
    EXPECT_EQ(u16(wav, 20), 1);        // PCM
    EXPECT_EQ(u16(wav, 22), 2);        // channels
    EXPECT_EQ(u32(wav, 24), 44100u);   // sample rate
    EXPECT_EQ(u32(wav, 28), 44100u * 4);  // byte rate
    EXPECT_EQ(u16(wav, 32), 4);        // block align
    EXPECT_EQ(u16(wav, 34), 16);       // bits per sample
    EXPECT_EQ(tag(wav, 36), "data");
    EXPECT_EQ(u32(wav, 40), 12u);      // data size
    EXPECT_EQ(pcm(wav, 0, 0), 0);
    EXPECT_EQ(pcm(wav, 0, 1), 32767);
    EXPECT_EQ(pcm(wav, 1, 0), -32767);
    EXPECT_EQ(pcm(wav, 1, 1), 16384);  // round(0.5 * 32767) = round(16383.5)
    EXPECT_EQ(pcm(wav, 2, 0), 32767);  // clamped
    EXPECT_EQ(pcm(wav, 2, 1), -32767);
}

TEST(WavFile, NanBecomesSilenceAndAnUnpairedValueIsDropped) {
    const std::vector<float> samples = {std::nanf(""), 0.25f, 0.75f};
    const std::vector<std::uint8_t> wav = encodeWav16(samples, 48000);
    ASSERT_EQ(wav.size(), 48u);
    EXPECT_EQ(u32(wav, 40), 4u);
    EXPECT_EQ(pcm(wav, 0, 0), 0);
    EXPECT_EQ(pcm(wav, 0, 1), 8192);  // round(8191.75)
}

TEST(WavFile, ASineWrittenAndReadBackHasItsLengthAndFrequency) {
    TestFolder folder;
    const double seconds = 2.0;
    const std::vector<float> samples = stereoSine(440.0, seconds, 44100, 0.8f);
    const fs::path path = folder.path / "out" / "sound.wav";
    Status written = writeWav16(path, samples, 44100);
    ASSERT_TRUE(written.ok()) << written.error().text();
    const std::vector<std::uint8_t> wav = readAll(path);
    ASSERT_EQ(wav.size(), 44u + 88200u * 4);
    const std::size_t frames = u32(wav, 40) / 4;
    EXPECT_EQ(frames, 88200u);
    int crossings = 0, peak = 0;
    for (std::size_t i = 1; i < frames; ++i) {
        const int a = pcm(wav, i - 1, 0), b = pcm(wav, i, 0);
        if ((a < 0) != (b < 0)) ++crossings;
        peak = std::max(peak, std::abs(b));
    }
    EXPECT_NEAR(crossings, 440 * seconds * 2, 2);
    EXPECT_NEAR(peak, 0.8 * 32767, 2);
    EXPECT_EQ(folder.files(), std::vector<std::string>{"sound.wav"});  // no temporary left
}

TEST(WavFile, AFailedWriteLeavesNoFile) {
    TestFolder folder;
    folder.write("occupied", "a file where the output's folder should be");
    const fs::path path = folder.path / "occupied" / "sound.wav";
    Status written = writeWav16(path, stereoSine(440.0, 0.1, 44100, 0.5f), 44100);
    ASSERT_FALSE(written.ok());
    EXPECT_NE(written.error().text().find("occupied"), std::string::npos) << written.error().text();
    EXPECT_EQ(folder.files(), std::vector<std::string>{"occupied"});
}

TEST(WavFile, BadArgumentsAreErrorsAndWriteNothing) {
    TestFolder folder;
    const fs::path path = folder.path / "sound.wav";
    const std::vector<float> odd = {0.1f, 0.2f, 0.3f};
    Status oddCount = writeWav16(path, odd, 44100);
    ASSERT_FALSE(oddCount.ok());
    EXPECT_EQ(oddCount.error().first().code, Code::CaptureWav);
    EXPECT_NE(oddCount.error().text().find("3 values are not whole left/right pairs"), std::string::npos);
    Status zeroRate = writeWav16(path, std::vector<float>{0.0f, 0.0f}, 0);
    ASSERT_FALSE(zeroRate.ok());
    EXPECT_EQ(zeroRate.error().first().code, Code::CaptureWav);
    EXPECT_TRUE(folder.files().empty());
}

// ---- SoundEncoding ---------------------------------------------------------------------------

TEST(SoundEncoding, WhatTheSiteDecodesForChosenValues) {
    // x = -1: v = 0.
    EXPECT_EQ(soundBytes(-1.0f).lo, 0);
    EXPECT_EQ(soundBytes(-1.0f).hi, 0);
    EXPECT_EQ(decodeSoundSample(0, 0), -1.0f);
    // x = 0: v = 32768 = hi 128 -> slightly above 0.
    EXPECT_EQ(soundBytes(0.0f).lo, 0);
    EXPECT_EQ(soundBytes(0.0f).hi, 128);
    EXPECT_FLOAT_EQ(decodeSoundSample(0, 128), static_cast<float>(-1.0 + 65536.0 / 65535.0));
    EXPECT_NEAR(decodeSoundSample(0, 128), 1.5259e-5, 1e-8);
    // x = 0.5: v = 49152 = hi 192.
    EXPECT_EQ(soundBytes(0.5f).lo, 0);
    EXPECT_EQ(soundBytes(0.5f).hi, 192);
    EXPECT_NEAR(decodeSoundSample(0, 192), 0.500023, 1e-6);
    // x = 1: v = 65536; lo = mod(65536, 256) = 0 and hi = 256/255 clamps to 255 on store: the
    // site plays 65280, i.e. 0.992218, not 1.
    EXPECT_EQ(soundBytes(1.0f).lo, 0);
    EXPECT_EQ(soundBytes(1.0f).hi, 255);
    EXPECT_NEAR(decodeSoundSample(0, 255), 0.992218, 1e-6);
    EXPECT_EQ(soundCode(1.0f), 65535);  // the code it was meant to be
    EXPECT_EQ(decodeSoundSample(255, 255), 1.0f);
}

TEST(SoundEncoding, RoundTripOfChosenValues) {
    struct Case {
        float x;
        std::uint16_t code;
    };
    for (const Case& c : {Case{-1.0f, 0}, Case{-0.5f, 16384}, Case{0.0f, 32768}, Case{0.25f, 40960},
                          Case{0.3f, 42598}, Case{0.999f, 65503}}) {
        EXPECT_EQ(soundCode(c.x), c.code) << c.x;
        const SoundBytes bytes = soundBytes(c.x);
        EXPECT_EQ(bytes.lo, c.code % 256) << c.x;
        EXPECT_EQ(bytes.hi, c.code / 256) << c.x;
        const float decoded = decodeSoundSample(bytes.lo, bytes.hi);
        EXPECT_EQ(decoded, static_cast<float>(-1.0 + 2.0 * c.code / 65535.0)) << c.x;
        EXPECT_NEAR(decoded, c.x, 2.0 / 65535.0) << c.x;
    }
}

TEST(SoundEncoding, OutOfRangeValuesStoreWhatTheRgba8TargetKeeps) {
    EXPECT_EQ(soundCode(-2.0f), 0);
    EXPECT_EQ(soundCode(3.0f), 65535);
    // x = -1.5: v = -16384, mod(v, 256) = 0, floor(v/256) = -64 -> 0.
    EXPECT_EQ(soundBytes(-1.5f).lo, 0);
    EXPECT_EQ(soundBytes(-1.5f).hi, 0);
    // v = floor(0.5 * 65536 * (1 + x)) with x slightly below -1 keeps a low byte: mod(-1, 256) = 255.
    const float justBelow = -1.0f - 1.0f / 32768.0f;  // v = -1
    EXPECT_EQ(soundBytes(justBelow).lo, 255);
    EXPECT_EQ(soundBytes(justBelow).hi, 0);
    EXPECT_EQ(soundBytes(std::nanf("")).lo, 0);
    EXPECT_EQ(soundBytes(std::nanf("")).hi, 0);
    EXPECT_EQ(soundBytes(INFINITY).hi, 255);
}

TEST(SoundEncoding, ABlockDecodesInReadingOrder) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(kSoundBlockSamples) * 4, 0);
    auto put = [&](std::size_t sample, std::uint16_t left, std::uint16_t right) {
        rgba[4 * sample + 0] = static_cast<std::uint8_t>(left & 0xFF);
        rgba[4 * sample + 1] = static_cast<std::uint8_t>(left >> 8);
        rgba[4 * sample + 2] = static_cast<std::uint8_t>(right & 0xFF);
        rgba[4 * sample + 3] = static_cast<std::uint8_t>(right >> 8);
    };
    put(0, 65535, 0);
    put(511, 32768, 49152);
    put(512, 16384, 1);  // the first sample of row 1
    put(262143, 300, 65280);
    std::vector<float> stereo(static_cast<std::size_t>(kSoundBlockSamples) * 2, 7.0f);
    decodeSoundBlock(rgba, stereo);
    EXPECT_EQ(stereo[0], 1.0f);
    EXPECT_EQ(stereo[1], -1.0f);
    EXPECT_EQ(stereo[2 * 511], decodeSoundSample(0, 128));
    EXPECT_EQ(stereo[2 * 511 + 1], decodeSoundSample(0, 192));
    EXPECT_EQ(stereo[2 * 512], decodeSoundSample(0, 64));
    EXPECT_EQ(stereo[2 * 512 + 1], decodeSoundSample(1, 0));
    EXPECT_EQ(stereo[2 * 262143], decodeSoundSample(300 & 0xFF, 300 >> 8));
    EXPECT_EQ(stereo[2 * 262143 + 1], decodeSoundSample(0, 255));
    EXPECT_EQ(stereo[2 * 1000], -1.0f);  // zero bytes

    // A short output decodes what fits and leaves the rest alone.
    std::vector<float> shortOut(3, 7.0f);
    decodeSoundBlock(rgba, shortOut);
    EXPECT_EQ(shortOut[0], 1.0f);
    EXPECT_EQ(shortOut[1], -1.0f);
    EXPECT_EQ(shortOut[2], 7.0f);
}
