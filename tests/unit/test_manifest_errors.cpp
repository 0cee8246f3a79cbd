// ManifestLoader: every validation error, with the exact location (file, pass, channel, field) in
// its message, and several problems reported together. Manifests are written to a temp folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "DiagnosticText.h"
#include "ManifestFolder.h"
#include "TestFolder.h"
#include "manifest/ManifestLoader.h"

using namespace toyhost;
namespace fs = std::filesystem;
using toyhost::testing::ManifestFolder;
using toyhost::testing::imageWithChannels;

namespace {


const std::string kImageCh0 = R"(passes."Image".channels.iChannel0)";
const std::string kImageCh1 = R"(passes."Image".channels.iChannel1)";

std::string errorOf(const Result<ManifestDesc>& result) {
    EXPECT_FALSE(result.ok());
    return result.ok() ? std::string("<no error>") : toyhost::testing::plainText(result.error());
}

}  // namespace

TEST(ManifestErrors, InvalidJsonNamesFileAndSaysInvalidJson) {
    ManifestFolder f;
    const std::string message = errorOf(f.parse(R"({"passes": {"Image": )"));
    EXPECT_EQ(message.rfind(f.manifest().string() + ":1:22: invalid JSON: the text ends too early", 0), 0u) << message;
}

TEST(ManifestErrors, RootMustBeAnObject) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"([{"passes": {}}])")), f.line("", "the manifest must be a JSON object"));
    EXPECT_EQ(errorOf(f.parse("42")), f.line("", "the manifest must be a JSON object"));
}

TEST(ManifestErrors, UnknownTopLevelField) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"shader": 1, "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line("", R"(unknown field "shader" (known: common, defaults, media, name, passes))"));
}

TEST(ManifestErrors, NameMustBeANonEmptyString) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"name": 3, "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line("", R"("name" must be a non-empty string, not the number 3)"));
    // Not "..., not string": the value is a string, an empty one.
    EXPECT_EQ(errorOf(f.parse(R"({"name": "", "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line("", R"("name" must be a non-empty string, not an empty string)"));
}

TEST(ManifestErrors, MissingEmptyOrNonObjectPasses) {
    ManifestFolder f;
    const std::string expected =
        f.line("passes", R"(must be an object with an "Image" pass and optionally "Buffer A" .. "Buffer D", "Cube A", "Sound")");
    EXPECT_EQ(errorOf(f.parse(R"({"name": "x"})")), expected);
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {}})")), expected);
    EXPECT_EQ(errorOf(f.parse(R"({"passes": [{"source": "image.glsl"}]})")), expected);
}

TEST(ManifestErrors, UnknownPassName) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "Buffer E": {"source": "x"}}})")),
              f.line(R"(passes."Buffer E")", "unknown pass (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound)"));
    // Pass names are exact: the loader does not guess at "image" or "A".
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "A": {"source": "buffer_a.glsl"}}})")),
              f.line(R"(passes."A")", "unknown pass (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound)"));
}

TEST(ManifestErrors, MissingImagePass) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"}}})")),
              f.line("passes", R"(the "Image" pass is missing)"));
}

TEST(ManifestErrors, PassBodyMustBeAnObject) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": "image.glsl"}})")),
              f.line(R"(passes."Image")", R"(must be an object with "source" and "channels")"));
}

TEST(ManifestErrors, UnknownPassField) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl", "code": "..."}}})")),
              f.line(R"(passes."Image")", R"(unknown field "code" (known: channels, source))"));
}

TEST(ManifestErrors, MissingSource) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"channels": []}}})")),
              f.line(R"(passes."Image")", R"("source" is missing)"));
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": ""}}})")),
              f.line(R"(passes."Image")", R"("source" must be a non-empty string, not an empty string)"));
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": ["image.glsl"]}}})")),
              f.line(R"(passes."Image")", R"("source" must be a non-empty string, not an array of 1 value)"));
}

TEST(ManifestErrors, SourceFileNotFoundNamesTheResolvedPath) {
    ManifestFolder f;
    const fs::path resolved = f.dir / "shaders" / "missing.glsl";
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "shaders/sub/../missing.glsl"}}})")),
              f.line(R"(passes."Image".source)", resolved.string() + ": file not found"));
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "Buffer B": {"source": "nope.glsl"}}})")),
              f.line(R"(passes."Buffer B".source)", (f.dir / "nope.glsl").string() + ": file not found"));
}

TEST(ManifestErrors, CommonFileNotFound) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"common": "common.glsl", "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line("common", (f.dir / "common.glsl").string() + ": file not found"));
}

TEST(ManifestErrors, ChannelsMustBeObjectOrArray) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"("A")"))),
              f.line(R"(passes."Image".channels)", "must be an object keyed iChannel0..iChannel3 or an array"));
}

TEST(ManifestErrors, UnknownChannelKey) {
    ManifestFolder f;
    const std::string where = R"(passes."Image".channels)";
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel4": {"buffer": "A"}})"))),
              f.line(where, R"(unknown channel "iChannel4" (known: iChannel0..iChannel3))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"channel0": {"buffer": "A"}})"))),
              f.line(where, R"(unknown channel "channel0" (did you mean "iChannel0"?) (known: iChannel0..iChannel3))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel01": {"buffer": "A"}})"))),
              f.line(where, R"(unknown channel "iChannel01" (did you mean "iChannel0"?) (known: iChannel0..iChannel3))"));
}

TEST(ManifestErrors, MoreThanFourChannelsInArrayForm) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"([null, null, null, null, {"buffer": "A"}])"))),
              f.line(R"(passes."Image".channels)", "at most 4 channels, got 5"));
}

TEST(ManifestErrors, ChannelMustBeObjectOrNull) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"([null, "A"])"))),
              f.line(kImageCh1, R"(must be an object such as {"buffer": "A"}, or null)"));
}

TEST(ManifestErrors, ChannelNeedsExactlyOneSource) {
    ManifestFolder f;
    const std::string what = R"(needs exactly one of "buffer", "texture", "media", "keyboard", "cubemap", "volume", "video", "music", "webcam", "mic")";
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel1": {"filter": "linear"}})"))), f.line(kImageCh1, what));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel1": {}})"))), f.line(kImageCh1, what));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel1": {"buffer": "A", "texture": "tex.png"}})"))),
              f.line(kImageCh1, what));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"([null, {"keyboard": true, "media": "Abstract 3"}])"))),
              f.line(kImageCh1, what));
}

TEST(ManifestErrors, UnknownChannelField) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "srgb": false}})"))),
              f.line(kImageCh0, R"(unknown field "srgb" (known: buffer, cubemap, filter, keyboard, kind, media, mic, music, texture, vflip, video, volume, webcam, wrap))"));
}

TEST(ManifestErrors, BufferThatDoesNotExist) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "E"}})"))),
              f.line(kImageCh0, R"(buffer "E" does not exist (known: A, B, C, D, Cube A))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "a"}})"))),
              f.line(kImageCh0, R"(buffer "a" does not exist (known: A, B, C, D, Cube A))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": 0}})"))),
              f.line(kImageCh0, R"("buffer" must be a non-empty string, not the number 0)"));
}

TEST(ManifestErrors, ReadingABufferWhosePassIsNotDefined) {
    ManifestFolder f;
    // imageWithChannels defines only Buffer A.
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "B"}})"))),
              f.line(kImageCh0, "reads Buffer B, which this manifest does not define"));
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Buffer A": {"source": "buffer_a.glsl", "channels": [null, null, {"buffer": "Buffer D"}]},
                                            "Image": {"source": "image.glsl"}}})")),
              f.line(R"(passes."Buffer A".channels.iChannel2)", "reads Buffer D, which this manifest does not define"));
}

TEST(ManifestErrors, TextureFileNotFound) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "textures/missing.png"}})"))),
              f.line(kImageCh0, "texture " + (f.dir / "textures" / "missing.png").string() + ": file not found"));
    // A folder is not a texture file.
    fs::create_directories(f.dir / "folder.png");
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "folder.png"}})"))),
              f.line(kImageCh0, "texture " + (f.dir / "folder.png").string() + ": is a folder, not a file"));
    // Links that lead nowhere say so; a device is not a texture either.
    fs::create_symlink("loop.png", f.dir / "loop.png");
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "loop.png"}})"))),
              f.line(kImageCh0, "texture " + (f.dir / "loop.png").string() + ": is a symbolic link loop"));
    fs::create_symlink("gone.png", f.dir / "dangling.png");
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "dangling.png"}})"))),
              f.line(kImageCh0, "texture " + (f.dir / "dangling.png").string() +
                                    ": is a symbolic link to nothing (its target is missing)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "/dev/zero"}})"))),
              f.line(kImageCh0, "texture /dev/zero: is not a regular file (a device, FIFO or socket)"));
}

TEST(ManifestErrors, UnknownStockMediaId) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"media": "Abstract 9"}})"))),
              f.line(kImageCh0, R"(unknown stock media "Abstract 9" (use a /media/a/<hash>.<ext> id, a stock name such as "Abstract 3", or add it to "media" with a file))"));
    // A Shadertoy media path the table does not know is accepted: it runs with a flagged stand-in.
    EXPECT_TRUE(f.parse(imageWithChannels(R"({"iChannel0": {"media": "/media/a/deadbeef.jpg"}})")).ok());
}

TEST(ManifestErrors, BadFilterWrapAndVflipValues) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "filter": "trilinear"}})"))),
              f.line(kImageCh0, R"(filter "trilinear" is not one of nearest, linear, mipmap)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "tex.png", "filter": "Linear"}})"))),
              f.line(kImageCh0, R"(filter "Linear" (did you mean "linear"?) is not one of nearest, linear, mipmap)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "wrap": "mirror"}})"))),
              f.line(kImageCh0, R"(wrap "mirror" is not one of clamp, repeat)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "wrap": 1}})"))),
              f.line(kImageCh0, R"("wrap" must be a non-empty string, not the number 1)"));
    // Exports write vflip as the string "true"; the manifest wants a JSON boolean.
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"texture": "tex.png", "vflip": "true"}})"))),
              f.line(kImageCh0, R"("vflip" must be true or false)"));
}

TEST(ManifestErrors, VflipOnABuffer) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "vflip": false}})"))),
              f.line(kImageCh0, R"("vflip" applies only to image textures, cubemaps and videos, not buffer channels)"));
}

TEST(ManifestErrors, SamplerSettingsOnKeyboard) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"keyboard": true, "filter": "nearest"}})"))),
              f.line(kImageCh0, R"(the keyboard texture takes no "filter" (it is always nearest/clamp))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"keyboard": true, "wrap": "clamp", "vflip": false}})"))),
              f.line(kImageCh0, R"(the keyboard texture takes no "wrap" (it is always nearest/clamp))") + "\n" +
                  f.line(kImageCh0, R"(the keyboard texture takes no "vflip" (it is always nearest/clamp))"));
}

TEST(ManifestErrors, KeyboardMustBeTrue) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"keyboard": false}})"))),
              f.line(kImageCh0, R"("keyboard" must be true)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"keyboard": 1}})"))),
              f.line(kImageCh0, R"("keyboard" must be true)"));
}

TEST(ManifestErrors, MediaMustBeAnObject) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"media": ["tex.png"], "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line("media", "must be an object mapping stock media ids to files"));
}

TEST(ManifestErrors, MediaOverrideFileMustBeAStringNamingAFile) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"media": {"Abstract 3": 7}, "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line(R"(media."Abstract 3")", "must be a file path string, not the number 7"));
    EXPECT_EQ(errorOf(f.parse(R"({"media": {"Abstract 3": "photos/abstract3.jpg"}, "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line(R"(media."Abstract 3")", (f.dir / "photos" / "abstract3.jpg").string() + ": file not found"));
}

TEST(ManifestErrors, MediaOverrideThatIsNeitherStockNorUsed) {
    ManifestFolder f;
    // A misspelt stock hash would otherwise be silently ignored.
    EXPECT_EQ(errorOf(f.parse(R"({"media": {"/media/a/8979352a.jpg": "tex.png"}, "passes": {"Image": {"source": "image.glsl"}}})")),
              f.line(R"(media."/media/a/8979352a.jpg")", "not a stock media id, and no channel uses it"));
}

TEST(ManifestErrors, SeveralProblemsReportedTogetherOnePerLine) {
    ManifestFolder f;
    const std::string json = R"({
        "extra": true,
        "passes": {
            "Image": {"source": "image.glsl",
                      "channels": {"iChannel0": {"buffer": "E"}, "iChannel1": {"buffer": "C"},
                                   "iChannel2": {"texture": "none.png", "wrap": "mirror"}}},
            "Buffer A": {"source": "missing_a.glsl", "channels": [{"keyboard": false}]}
        }
    })";
    const std::string expected =
        f.line("", R"(unknown field "extra" (known: common, defaults, media, name, passes))") + "\n" +
        f.line(R"(passes."Buffer A".source)", (f.dir / "missing_a.glsl").string() + ": file not found") + "\n" +
        f.line(R"(passes."Buffer A".channels.iChannel0)", R"("keyboard" must be true)") + "\n" +
        f.line(kImageCh0, R"(buffer "E" does not exist (known: A, B, C, D, Cube A))") + "\n" +
        f.line(R"(passes."Image".channels.iChannel2)", "texture " + (f.dir / "none.png").string() + ": file not found") + "\n" +
        f.line(R"(passes."Image".channels.iChannel2)", R"(wrap "mirror" is not one of clamp, repeat)") + "\n" +
        f.line(kImageCh1, "reads Buffer C, which this manifest does not define");
    EXPECT_EQ(errorOf(f.parse(json)), expected);
}

TEST(ManifestErrors, LoadManifestOnAMissingFolderOrFile) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(loadManifest(f.dir / "absent")), (f.dir / "absent").string() + ": file not found");
    EXPECT_EQ(errorOf(loadManifest(f.dir)), (f.dir / "manifest.json").string() + ": file not found");
}

TEST(ManifestErrors, LoadManifestReportsProblemsAgainstTheFile) {
    ManifestFolder f;
    f.write("manifest.json", R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"}}})");
    EXPECT_EQ(errorOf(loadManifest(f.dir)), f.line("passes", R"(the "Image" pass is missing)"));
}

// 4 million bad "media" entries took 210 s and 5.5 GB: every problem was collected (and each file
// looked for) although only 100 are printed. Validation stops at defaults::kMaxManifestProblems and
// says so; the entries after the first 50 (in key order) are not looked at, so 200000 of them leave
// 50 problems and the note, not 200000 problems.
TEST(ManifestErrors, ValidationStopsAfterTheProblemLimitAndSaysSo) {
    ManifestFolder f;
    std::string media;
    for (int i = 0; i < 200000; ++i)
        media += (i ? ", " : "") + std::string("\"m") + std::to_string(1000000 + i) + "\": \"missing" + std::to_string(i) + ".png\"";
    const Result<ManifestDesc> result =
        f.parse(R"({"passes": {"Image": {"source": "image.glsl"}}, "media": {)" + media + "}}");
    ASSERT_FALSE(result.ok());
    const std::vector<Diagnostic>& all = result.error().diagnostics;
    ASSERT_EQ(all.size(), 51u);
    for (std::size_t i = 0; i < 50; ++i) {
        EXPECT_EQ(all[i].severity, Severity::Error);
        EXPECT_EQ(all[i].field, "media.\"m" + std::to_string(1000000 + i) + "\"");
    }
    EXPECT_EQ(all[50].severity, Severity::Notice);
    EXPECT_EQ(all[50].file, f.manifest().string());
    EXPECT_EQ(all[50].message, "stopped after 50 problems; the rest of the manifest was not checked (fix these and run again)");
    // The printed list shows every problem and the note, with no "... and N more" to suggest a count.
    const std::string text = result.error().text();
    EXPECT_EQ(text.find("more"), std::string::npos) << text.substr(text.size() - 300);
}
