// ChannelMedia: every media channel made ready before GL. Videos and audio are opened here (off the
// GL thread), and every broken one is reported at once with its pass, channel and file; notices
// name stock media by name, say which supplied file a stock id uses, and warn when its size is not
// the stock one's. No GL needed.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "DiagnosticText.h"
#include "TestFolder.h"
#include "core/ChildProcess.h"
#include "image/ImageWriters.h"
#include "manifest/ManifestLoader.h"
#include "media/ChannelMedia.h"

using namespace toyhost;
using toyhost::testing::TestFolder;
namespace fs = std::filesystem;

namespace {

bool haveFfmpeg() { return findExecutable("ffmpeg") && findExecutable("ffprobe"); }

Result<ChannelMedia> loadFolder(const TestFolder& folder, const std::string& manifest, const MediaOptions& options = {}) {
    folder.write("image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n");
    folder.write("buffer.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n");
    const fs::path path = folder.write("manifest.json", manifest);
    Result<ManifestDesc> desc = loadManifest(path);
    if (!desc) return desc.error();
    return ChannelMedia::load(*desc, makeMediaResolver(*desc, options), options);
}

fs::path writeSolidPng(const fs::path& path, int width, int height) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * height * 4, 128);
    EXPECT_TRUE(writePng(path, width, height, rgba));
    return path;
}

// The notices of `media` with `code`, as plain lines.
std::vector<std::string> noticesWith(const ChannelMedia& media, Code code) {
    std::vector<std::string> lines;
    for (const Diagnostic& d : media.notices())
        if (d.code == code) lines.push_back(toyhost::testing::plainLine(d));
    return lines;
}

}  // namespace

TEST(ChannelMedia, EveryBrokenVideoAndMusicInputIsReportedAtOnce) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    folder.write("a.mp4", "not a video\n");
    folder.write("b.mkv", "not a video either\n");
    folder.write("c.mp3", "not music\n");
    folder.write("d.wav", "RIFF nonsense\n");
    const Result<ChannelMedia> media = loadFolder(folder, R"({"passes": {
        "Buffer A": {"source": "buffer.glsl", "channels": {"iChannel2": {"music": "d.wav"}}},
        "Image": {"source": "image.glsl", "channels": {"iChannel0": {"video": "a.mp4"}, "iChannel1": {"video": "b.mkv"},
                                                       "iChannel3": {"music": "c.mp3"}}}}})");
    ASSERT_FALSE(media);
    const std::vector<Diagnostic>& problems = media.error().diagnostics;
    ASSERT_EQ(problems.size(), 4u) << media.error().text();
    const struct {
        const char* pass;
        int channel;
        const char* file;
    } expected[] = {{"Buffer A", 2, "d.wav"}, {"Image", 0, "a.mp4"}, {"Image", 1, "b.mkv"}, {"Image", 3, "c.mp3"}};
    for (std::size_t i = 0; i < problems.size(); ++i) {
        EXPECT_EQ(problems[i].pass, expected[i].pass) << i;
        EXPECT_EQ(problems[i].channel, expected[i].channel) << i;
        EXPECT_EQ(problems[i].file, (folder.path / expected[i].file).string()) << i;
        EXPECT_EQ(problems[i].severity, Severity::Error) << i;
    }
    EXPECT_EQ(problems[1].code, Code::VideoProbe);
    EXPECT_EQ(problems[3].code, Code::AudioDecode);
}

TEST(ChannelMedia, VideosAndMusicAreOpenedWhileThePlanIsMade) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    ASSERT_EQ(std::system(("ffmpeg -v error -nostdin -f lavfi -i testsrc2=s=48x32:r=25:d=1 -c:v ffv1 '" +
                           (folder.path / "clip.mkv").string() + "'").c_str()), 0);
    ASSERT_EQ(std::system(("ffmpeg -v error -nostdin -f lavfi -i sine=d=0.5 '" + (folder.path / "tone.wav").string() + "'")
                              .c_str()), 0);
    const Result<ManifestDesc> desc = [&] {
        folder.write("image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.0); }\n");
        return loadManifest(folder.write("manifest.json", R"({"passes": {"Image": {"source": "image.glsl",
            "channels": {"iChannel0": {"video": "clip.mkv"}, "iChannel1": {"music": "tone.wav"}, "iChannel2": {"webcam": true}}}}})"));
    }();
    ASSERT_TRUE(desc) << desc.error().text();
    const Result<ChannelMedia> media = ChannelMedia::load(*desc, makeMediaResolver(*desc, {}));
    ASSERT_TRUE(media) << media.error().text();
    const PassDesc& image = desc->passes.back();
    const TimedMedia* video = media->findTimed(image.channels[0]);
    ASSERT_TRUE(video && video->video);
    EXPECT_EQ(video->video->width(), 48);  // probed
    EXPECT_EQ(video->video->current().width, 48);  // and its first frame decoded
    const TimedMedia* music = media->findTimed(image.channels[1]);
    ASSERT_TRUE(music && music->clip);
    EXPECT_EQ(music->clip->mono.size(), 22050u);  // decoded whole: 0.5 s at 44100 Hz
    const TimedMedia* webcam = media->findTimed(image.channels[2]);
    ASSERT_TRUE(webcam);
    EXPECT_TRUE(webcam->standIn());
}

TEST(ChannelMedia, StandInNoticesNameTheStockMediaTheUserCanSupplyByName) {
    TestFolder folder;
    const Result<ChannelMedia> media = loadFolder(folder, R"({"passes": {"Image": {"source": "image.glsl", "channels": {
        "iChannel0": {"media": "/media/a/8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683.jpg"},
        "iChannel1": {"media": "Forest"}, "iChannel2": {"media": "Grey Noise3D"}, "iChannel3": {"media": "Lichen"}}}}})");
    ASSERT_TRUE(media) << media.error().text();
    const std::vector<std::string> notices = noticesWith(*media, Code::MediaStandIn);
    ASSERT_EQ(notices.size(), 4u);
    for (const std::string& expected : {std::string("--media-file \"Abstract 3=<path>\""), std::string("--media-file Forest=FILE"),
                                        std::string("--media-file \"Grey Noise3D=FILE\""), std::string("--media-file Lichen=<path>")})
        EXPECT_TRUE(std::any_of(notices.begin(), notices.end(),
                                [&](const std::string& line) { return line.find(expected) != std::string::npos; }))
            << expected << " is in no notice:\n" << notices[0] << "\n" << notices[1] << "\n" << notices[2] << "\n" << notices[3];
    // The hash form is still named (it is the id the manifest wrote), but not offered as the option.
    for (const std::string& line : notices) EXPECT_EQ(line.find("--media-file 8979"), std::string::npos) << line;
}

TEST(ChannelMedia, ASuppliedFileIsConfirmedAndASizeThatDiffersIsAWarning) {
    TestFolder folder;
    const fs::path small = writeSolidPng(folder.path / "abstract3-small.png", 16, 16);
    const fs::path exact = writeSolidPng(folder.path / "gray-noise.png", 64, 64);
    const fs::path cross = writeSolidPng(folder.path / "forest-cross.png", 64, 48);  // a 4:3 cross of 16x16 faces
    MediaOptions options;
    // Names work as well as hashes, for textures and for the other stock inputs.
    options.files = {{"Abstract 3", small}, {"gray noise small", exact}, {"Forest", cross}};
    const Result<ChannelMedia> media = loadFolder(folder, R"({"passes": {"Image": {"source": "image.glsl", "channels": {
        "iChannel0": {"media": "Abstract 3"}, "iChannel1": {"media": "Gray Noise Small"},
        "iChannel2": {"media": "/media/a/94284d43be78f00eb6b298e6d78656a1b34e2b91b34940d02f1ca8b22310e8a0.png"}}}}})",
                                                  options);
    ASSERT_TRUE(media) << media.error().text();
    EXPECT_TRUE(media->standIns().empty());
    const std::vector<std::string> supplied = noticesWith(*media, Code::MediaSupplied);
    ASSERT_EQ(supplied.size(), 3u);
    EXPECT_EQ(supplied[0], "Image / iChannel0: stock texture 'Abstract 3': using the supplied file " + small.string() +
                               " (16x16)");
    EXPECT_EQ(supplied[1], "Image / iChannel1: stock texture 'Gray Noise Small': using the supplied file " +
                               exact.string() + " (64x64)");
    EXPECT_EQ(supplied[2], "Image / iChannel2: stock cubemap 'Forest': using the supplied file " + cross.string() +
                               " (16x16 faces)");
    const std::vector<std::string> mismatches = noticesWith(*media, Code::MediaSizeMismatch);
    ASSERT_EQ(mismatches.size(), 1u);  // only Abstract 3 differs; a cubemap's stock size is not known
    EXPECT_EQ(mismatches[0], "Image / iChannel0: stock texture 'Abstract 3' is 1024x1024 on shadertoy.com, but the "
                             "supplied file " + small.string() + " is 16x16: a shader that depends on the size "
                             "(texel lookups, hash tables) will not look as on the site");
    for (const Diagnostic& d : media->notices())
        EXPECT_EQ(d.severity, d.code == Code::MediaSizeMismatch ? Severity::Warning : Severity::Notice);
}

TEST(ChannelMedia, ASuppliedVolumeOfAnotherSizeIsAWarning) {
    TestFolder folder;
    const Volume8 volume = volumeStandIn(8, 1, 7);
    const std::vector<std::uint8_t> bytes = encodeVolumeFile(volume);
    const fs::path file = folder.write("noise.bin", std::string(bytes.begin(), bytes.end()));
    MediaOptions options;
    options.folders = {};
    options.files = {{"Grey Noise3D", file}};
    const Result<ChannelMedia> media = loadFolder(
        folder, R"({"passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"media": "Grey Noise3D"}}}}})",
        options);
    ASSERT_TRUE(media) << media.error().text();
    const std::vector<std::string> mismatches = noticesWith(*media, Code::MediaSizeMismatch);
    ASSERT_EQ(mismatches.size(), 1u);
    EXPECT_NE(mismatches[0].find("stock volume 'Grey Noise3D' is 32x32x32 on shadertoy.com, but the supplied file " +
                                 file.string() + " is 8x8x8"),
              std::string::npos)
        << mismatches[0];
}

TEST(ChannelMedia, APlanMadeWhileAnotherHoldsASourceSharesItUntilTheFileChanges) {
    if (!haveFfmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
    TestFolder folder;
    ASSERT_EQ(std::system(("ffmpeg -v error -nostdin -f lavfi -i testsrc2=s=32x24:r=10:d=1 -c:v ffv1 '" +
                           (folder.path / "clip.mkv").string() + "'").c_str()), 0);
    ASSERT_EQ(std::system(("ffmpeg -v error -nostdin -f lavfi -i sine=d=0.3 '" + (folder.path / "tone.wav").string() + "'")
                              .c_str()), 0);
    const std::string manifest = R"({"passes": {"Image": {"source": "image.glsl", "channels": {
        "iChannel0": {"video": "clip.mkv"}, "iChannel1": {"music": "tone.wav"}, "iChannel2": {"mic": true}}}}})";
    MediaOptions options;
    options.mic = "lavfi:sine=frequency=440";  // a live source: opened once, however many plans use it
    Result<ChannelMedia> first = loadFolder(folder, manifest, options);
    ASSERT_TRUE(first) << first.error().text();
    Result<ChannelMedia> second = loadFolder(folder, manifest, options);  // a hot reload's plan
    ASSERT_TRUE(second) << second.error().text();
    const PassDesc image = [&] {
        Result<ManifestDesc> desc = loadManifest(folder.path / "manifest.json");
        return desc->passes.back();
    }();
    for (int c = 0; c < 3; ++c) {
        const TimedMedia* a = first->findTimed(image.channels[c]);
        const TimedMedia* b = second->findTimed(image.channels[c]);
        ASSERT_TRUE(a && b) << c;
        EXPECT_EQ(a->video, b->video) << c;
        EXPECT_EQ(a->clip, b->clip) << c;
        EXPECT_EQ(a->live, b->live) << c;
        EXPECT_FALSE(a->standIn()) << c;
    }
    // An edited file is opened again.
    ASSERT_EQ(std::system(("ffmpeg -v error -nostdin -y -f lavfi -i testsrc2=s=40x24:r=10:d=1 -c:v ffv1 '" +
                           (folder.path / "clip.mkv").string() + "'").c_str()), 0);
    Result<ChannelMedia> third = loadFolder(folder, manifest, options);
    ASSERT_TRUE(third) << third.error().text();
    const TimedMedia* edited = third->findTimed(image.channels[0]);
    ASSERT_TRUE(edited && edited->video);
    EXPECT_NE(edited->video, first->findTimed(image.channels[0])->video);
    EXPECT_EQ(edited->video->width(), 40);
}
