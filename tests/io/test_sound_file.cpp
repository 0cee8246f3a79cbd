// SoundFile: which output names `toyhost sound` accepts (by extension; "-" and devices as WAV
// streams), and that writing never throws: a name without an extension was std::out_of_range.
// No GL needed.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "TestFolder.h"
#include "capture/SoundFile.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

TEST(SoundFile, TheFormatIsChosenByTheExtensionAndAStreamIsWav) {
    TestFolder folder;
    for (const char* name : {"a.wav", "A.FLAC", "b.ogg", "c.opus", "d.mp3", "e.m4a"})
        EXPECT_TRUE(checkSoundOutput(folder.path / name)) << name;
    EXPECT_TRUE(checkSoundOutput("-"));
    EXPECT_TRUE(checkSoundOutput("/dev/null"));  // an existing device: written as a WAV stream
    for (const fs::path& name : {folder.path / "s", folder.path / "s.aiff", fs::path("")}) {
        const Status checked = checkSoundOutput(name);
        ASSERT_FALSE(checked) << name;
        EXPECT_EQ(checked.error().category(), Category::Usage) << name;
        EXPECT_EQ(checked.error().first().code, Code::UsageOut) << name;
    }
    EXPECT_NE(checkSoundOutput(folder.path / "s").error().first().message.find(".wav, .flac, .ogg, .opus, .mp3 or .m4a"),
              std::string::npos);
    fs::create_directories(folder.path / "folder.wav");
    EXPECT_EQ(checkSoundOutput(folder.path / "folder.wav").error().first().message, "is a folder, not a file");
}

TEST(SoundFile, WritingNeverThrowsAndLeavesNothingOnFailure) {
    TestFolder folder;
    const std::vector<float> stereo(2 * 4410, 0.5f);
    // A name without an extension: an error, no file, no exception.
    EXPECT_FALSE(writeSoundFile(folder.path / "s", stereo));
    EXPECT_FALSE(writeSoundFile(folder.path / "odd.wav", std::vector<float>(3, 0.0f)));
    EXPECT_TRUE(fs::is_empty(folder.path));
    // A WAV file: complete, under its name only.
    ASSERT_TRUE(writeSoundFile(folder.path / "tone.wav", stereo));
    EXPECT_EQ(fs::file_size(folder.path / "tone.wav"), 44u + 4410u * 4u);
    // /dev/null takes the stream.
    EXPECT_TRUE(writeSoundFile("/dev/null", stereo));
    // A full device: the reason in the usual words.
    const Status full = writeSoundFile("/dev/full", stereo);
    ASSERT_FALSE(full);
    EXPECT_EQ(full.error().first().code, Code::IoNoSpace);
    EXPECT_EQ(full.error().first().file, "/dev/full");
    EXPECT_EQ(full.error().first().message, "write failed: No space left on device");
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder.path)) names.push_back(entry.path().filename().string());
    EXPECT_EQ(names, std::vector<std::string>{"tone.wav"});
}
