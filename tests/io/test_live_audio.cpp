// LiveAudio: a live mic source through an ffmpeg child (tested with a synthetic lavfi source paced
// in real time, as a microphone would be): samples arrive, the newest window analyses to the
// tone's bin, a source ffmpeg cannot open is one clear error, and nothing is left running.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <vector>

#include "core/ChildProcess.h"
#include "media/AudioAnalyser.h"
#include "media/LiveAudio.h"

using namespace toyhost;

TEST(LiveAudio, KnowsWhichSourcesAreLive) {
    EXPECT_TRUE(LiveAudio::isLiveSource("alsa:hw:0"));
    EXPECT_TRUE(LiveAudio::isLiveSource("pulse:default"));
    EXPECT_TRUE(LiveAudio::isLiveSource("lavfi:sine=frequency=440"));
    EXPECT_FALSE(LiveAudio::isLiveSource("song.mp3"));
    EXPECT_FALSE(LiveAudio::isLiveSource("/dev/snd/pcmC0D0c"));
}

TEST(LiveAudio, ALiveToneFillsTheWindowAndPeaksInItsBin) {
    if (!findExecutable("ffmpeg")) GTEST_SKIP() << "needs ffmpeg";
    Result<std::unique_ptr<LiveAudio>> live = LiveAudio::open("lavfi:sine=frequency=1000:sample_rate=44100");
    ASSERT_TRUE(live) << live.error().text();
    std::vector<float> window(2048);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while ((*live)->latest(window) < 4096 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const std::uint64_t first = (*live)->latest(window);
    ASSERT_GE(first, 4096u);
    AudioAnalyser analyser;
    for (int i = 0; i < 8; ++i) analyser.analyse(window);
    const auto& texels = analyser.texels();
    const auto peak = std::max_element(texels.begin(), texels.begin() + 512) - texels.begin();
    EXPECT_EQ(peak, 46);  // 1000 Hz * 2048 / 44100 = 46.4
    // It keeps coming, at the pace of a real input (not all at once).
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const std::uint64_t later = (*live)->latest(window);
    EXPECT_GT(later, first + 4410);
    EXPECT_LT(later, first + 44100);
}

TEST(LiveAudio, ASourceFfmpegCannotOpenIsOneClearError) {
    if (!findExecutable("ffmpeg")) GTEST_SKIP() << "needs ffmpeg";
    Result<std::unique_ptr<LiveAudio>> live = LiveAudio::open("lavfi:this_is_not_a_filter=1");
    ASSERT_FALSE(live);
    const std::string text = live.error().text();
    EXPECT_NE(text.find("lavfi:this_is_not_a_filter=1: ffmpeg could not open it"), std::string::npos) << text;
    EXPECT_EQ(LiveAudio::open("song.mp3").error().first().code, Code::AudioLive);
}
