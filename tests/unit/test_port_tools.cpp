// Porting helpers: "did you mean" suggestions (Suggest, manifest near misses, stock media near
// misses), the manifest's "defaults" block, channels the code names but leaves unbound, gliding
// mouse moves in input scripts, and the `toyhost new` starter folders. No GL needed.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "DiagnosticText.h"
#include "ManifestFolder.h"
#include "TestFolder.h"
#include "core/Suggest.h"
#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "manifest/ManifestLoader.h"
#include "manifest/Starter.h"
#include "manifest/StockMedia.h"
#include "shader/ChannelUse.h"

using namespace toyhost;
namespace fs = std::filesystem;
using toyhost::testing::ManifestFolder;
using toyhost::testing::imageWithChannels;

namespace {

// ---- helpers --------------------------------------------------------------------------------


// An Image-only manifest with `defaults` (JSON text) as its "defaults" block.
std::string imageWithDefaults(const std::string& defaults) {
    return R"({"defaults": )" + defaults + R"(, "passes": {"Image": {"source": "image.glsl"}}})";
}

const std::string kImageChannels = R"(passes."Image".channels)";
const std::string kImageCh0 = R"(passes."Image".channels.iChannel0)";

std::string errorOf(const Result<ManifestDesc>& result) {
    EXPECT_FALSE(result.ok());
    return result.ok() ? std::string("<no error>") : toyhost::testing::plainText(result.error());
}

const std::vector<std::string> kPassNames{"Buffer A", "Buffer B", "Buffer C", "Buffer D", "Image"};
const std::vector<std::string> kChannelKeys{"iChannel0", "iChannel1", "iChannel2", "iChannel3"};
const std::vector<std::string> kFilters{"nearest", "linear", "mipmap"};

// The real stock texture "Gray Noise Medium" and two near misses of its id.
const std::string kGrayNoiseHash = "0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f5";
const std::string kGrayNoisePath = "/media/a/" + kGrayNoiseHash + ".png";
const std::string kGrayNoiseOneTypo =  // last hex digit 5 -> 6
    "/media/a/0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f6.png";
const std::string kAbstract3Path = "/media/a/8979352a182bde7c3c651ba2b2f4e0615de819585cc37b7175bcefbca15a6683.jpg";

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every file in `dir` (not recursive) by name, with its content.
std::map<std::string, std::string> folderContents(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::directory_iterator(dir)) files[entry.path().filename().string()] = readFile(entry.path());
    return files;
}

std::vector<PassId> passIds(const ManifestDesc& m) {
    std::vector<PassId> ids;
    for (const PassDesc& p : m.passes) ids.push_back(p.id);
    return ids;
}

std::array<bool, kChannelCount> named(bool c0, bool c1, bool c2, bool c3) { return {c0, c1, c2, c3}; }

// A pass built in code, as the loader would leave it.
PassDesc passWithCode(PassId id, const std::string& code) {
    PassDesc pass;
    pass.id = id;
    pass.source = fs::path("/toy") / (id == PassId::Image ? "image.glsl" : "buffer.glsl");
    pass.sourceName = pass.source.string();
    pass.code = code;
    return pass;
}

void bindBuffer(PassDesc& pass, int channel, int buffer) {
    pass.channels[channel].kind = ChannelKind::Buffer;
    pass.channels[channel].buffer = buffer;
}

std::string mouseError(const std::string& json) {
    auto result = parseMouseScript(json, "mouse.json");
    return result.ok() ? "(parsed without error)" : toyhost::testing::plainText(result.error());
}

// The events a player produces before each frame 0..lastFrame, at iTime = frame / fps.
std::vector<std::vector<InputEvent>> playFrames(const std::string& json, int lastFrame, double fps = 60.0) {
    auto script = parseMouseScript(json, "mouse.json");
    EXPECT_TRUE(script.ok()) << (script.ok() ? "" : script.error().text());
    if (!script.ok()) return {};
    MouseScriptPlayer player(std::move(*script));
    std::vector<std::vector<InputEvent>> frames(lastFrame + 1);
    for (int frame = 0; frame <= lastFrame; ++frame) player.eventsBeforeFrame(frame, frame / fps, frames[frame]);
    return frames;
}

std::string describe(const InputEvent& e) {
    const char* names[] = {"down", "move", "up", "keydown", "keyup"};
    std::ostringstream out;
    out << names[static_cast<int>(e.type)] << "(" << e.x << ", " << e.y << ")";
    return out.str();
}

std::string describe(const std::vector<InputEvent>& events) {
    std::string out = "[";
    for (const InputEvent& e : events) out += (out.size() > 1 ? ", " : "") + describe(e);
    return out + "]";
}

// Same types in the same order, coordinates equal to float rounding.
void expectEvents(const std::vector<InputEvent>& actual, const std::vector<InputEvent>& expected,
                  const std::string& what) {
    ASSERT_EQ(actual.size(), expected.size()) << what << ": got " << describe(actual) << ", expected "
                                              << describe(expected);
    for (std::size_t i = 0; i < actual.size(); ++i) {
        EXPECT_EQ(actual[i].type, expected[i].type) << what << " event " << i << ": " << describe(actual);
        EXPECT_NEAR(actual[i].x, expected[i].x, 1e-4) << what << " event " << i << ": " << describe(actual);
        EXPECT_NEAR(actual[i].y, expected[i].y, 1e-4) << what << " event " << i << ": " << describe(actual);
    }
}

const InputEvent kUp = InputEvent::mouseUp();
InputEvent down(float x, float y) { return InputEvent::mouseDown(x, y); }
InputEvent move(float x, float y) { return InputEvent::mouseMove(x, y); }

}  // namespace

// ---- 1. Suggest -------------------------------------------------------------------------------

TEST(PortToolsSuggest, EditDistanceCountsInsertionsDeletionsAndSubstitutions) {
    EXPECT_EQ(editDistance("buffer", "buffer"), 0u);
    EXPECT_EQ(editDistance("bufer", "buffer"), 1u);    // one insertion
    EXPECT_EQ(editDistance("bufffer", "buffer"), 1u);  // one deletion
    EXPECT_EQ(editDistance("biffer", "buffer"), 1u);   // one substitution
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("abc", ""), 3u);
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("image", "Image"), 1u);  // case-sensitive
    EXPECT_EQ(editDistance("abc", "ABC"), 3u);
}

TEST(PortToolsSuggest, AdjacentTranspositionCountsAsOneEdit) {
    EXPECT_EQ(editDistance("fitler", "filter"), 1u);
    EXPECT_EQ(editDistance("filter", "fitler"), 1u);
    EXPECT_EQ(editDistance("fsp", "fps"), 1u);
    EXPECT_EQ(editDistance("ab", "ba"), 1u);
    // Optimal string alignment: a transposed pair is not edited again ("ca" -> "abc" is 3, not 2).
    EXPECT_EQ(editDistance("ca", "abc"), 3u);
}

TEST(PortToolsSuggest, ClosestMatchFindsTypos) {
    const std::vector<std::string> channelFields{"buffer", "filter", "keyboard", "media", "texture", "vflip", "wrap"};
    EXPECT_EQ(closestMatch("bufer", channelFields), std::optional<std::string>("buffer"));
    EXPECT_EQ(closestMatch("fitler", channelFields), std::optional<std::string>("filter"));
    EXPECT_EQ(closestMatch("iChanel0", kChannelKeys), std::optional<std::string>("iChannel0"));
    EXPECT_EQ(closestMatch("neareest", kFilters), std::optional<std::string>("nearest"));
}

TEST(PortToolsSuggest, ClosestMatchIgnoresCaseAndSurroundingSpaces) {
    EXPECT_EQ(closestMatch("Image ", kPassNames), std::optional<std::string>("Image"));
    EXPECT_EQ(closestMatch("  Image", kPassNames), std::optional<std::string>("Image"));
    EXPECT_EQ(closestMatch("image", kPassNames), std::optional<std::string>("Image"));
    EXPECT_EQ(closestMatch("IMAGE", kPassNames), std::optional<std::string>("Image"));
    EXPECT_EQ(closestMatch("Buffer a", kPassNames), std::optional<std::string>("Buffer A"));
    EXPECT_EQ(closestMatch("buffer c", kPassNames), std::optional<std::string>("Buffer C"));
}

TEST(PortToolsSuggest, AnotherIndexIsNotATypo) {
    EXPECT_EQ(closestMatch("Buffer E", kPassNames), std::nullopt);
    EXPECT_EQ(closestMatch("buffer e", kPassNames), std::nullopt);
    EXPECT_EQ(closestMatch("iChannel4", kChannelKeys), std::nullopt);
    EXPECT_EQ(closestMatch("iChannel9", kChannelKeys), std::nullopt);
}

TEST(PortToolsSuggest, NothingFarIsSuggested) {
    EXPECT_EQ(closestMatch("xyz", kPassNames), std::nullopt);
    EXPECT_EQ(closestMatch("xyz", kChannelKeys), std::nullopt);
    EXPECT_EQ(closestMatch("blurry", kFilters), std::nullopt);
    EXPECT_EQ(closestMatch("anything", std::vector<std::string>{}), std::nullopt);
}

TEST(PortToolsSuggest, AllowedDistanceIsAThirdOfTheCandidateBetweenOneAndThree) {
    // "fps" (3 letters) allows 1 edit.
    EXPECT_EQ(closestMatch("fs", std::vector<std::string>{"fps"}), std::optional<std::string>("fps"));
    EXPECT_EQ(closestMatch("fqz", std::vector<std::string>{"fps"}), std::nullopt);  // 2 edits
    // "buffer" (6) allows 2 edits.
    EXPECT_EQ(closestMatch("bfer", std::vector<std::string>{"buffer"}), std::optional<std::string>("buffer"));
    EXPECT_EQ(closestMatch("bfe", std::vector<std::string>{"buffer"}), std::nullopt);  // 3 edits
    // A long candidate (20 letters) allows at most 3 edits.
    const std::vector<std::string> longName{"abcdefghijklmnopqrst"};
    EXPECT_EQ(closestMatch("abcdefghijklmnXXXrst", longName), std::optional<std::string>(longName[0]));  // 3 edits
    EXPECT_EQ(closestMatch("abcdefghijXXXXopqrst", longName), std::nullopt);  // 4 edits
}

TEST(PortToolsSuggest, TheTypedWordItselfIsNeverSuggested) {
    EXPECT_EQ(closestMatch("Image", kPassNames), std::nullopt);
    EXPECT_EQ(closestMatch("buffer", std::vector<std::string>{"buffer"}), std::nullopt);
    // The typed word is skipped, the next near candidate wins.
    EXPECT_EQ(closestMatch("Image", std::vector<std::string>{"Image", "Images"}), std::optional<std::string>("Images"));
    EXPECT_EQ(didYouMean("Image", kPassNames), "");
}

TEST(PortToolsSuggest, TheNearestCandidateWinsAndTiesGoToTheFirst) {
    EXPECT_EQ(closestMatch("Abstrac 3", std::vector<std::string>{"Abstract 1", "Abstract 3"}),
              std::optional<std::string>("Abstract 3"));  // 2 edits vs 1
    EXPECT_EQ(closestMatch("cat", std::vector<std::string>{"bat", "cot"}), std::optional<std::string>("bat"));
    EXPECT_EQ(closestMatch("cat", std::vector<std::string>{"cot", "bat"}), std::optional<std::string>("cot"));
}

TEST(PortToolsSuggest, DidYouMeanText) {
    EXPECT_EQ(didYouMean("bufer", std::vector<std::string>{"buffer", "filter"}), " (did you mean \"buffer\"?)");
    EXPECT_EQ(didYouMean("Image ", kPassNames), " (did you mean \"Image\"?)");
    EXPECT_EQ(didYouMean("xyz", kPassNames), "");
    EXPECT_EQ(didYouMean("Buffer E", kPassNames), "");
}

// ---- 2. Manifest near misses --------------------------------------------------------------------

TEST(PortToolsManifestNearMiss, MisspelledChannelFieldSuggestsBuffer) {
    ManifestFolder f;
    auto result = f.parse(imageWithChannels(R"({"iChannel0": {"bufer": "A"}})"));
    EXPECT_EQ(errorOf(result),
              // One typo, one message: the missing source is the misspelt "buffer".
              f.line(kImageCh0, R"(unknown field "bufer" (did you mean "buffer"?) )"
                                R"((known: buffer, cubemap, filter, keyboard, kind, media, mic, music, texture, vflip, video, volume, webcam, wrap))"));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().first().code, Code::ManifestUnknownField);
}

TEST(PortToolsManifestNearMiss, MisspelledChannelKeySuggestsIChannel) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChanel0": {"buffer": "A"}})"))),
              f.line(kImageChannels,
                     R"(unknown channel "iChanel0" (did you mean "iChannel0"?) (known: iChannel0..iChannel3))"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"ichannel2": {"buffer": "A"}})"))),
              f.line(kImageChannels,
                     R"(unknown channel "ichannel2" (did you mean "iChannel2"?) (known: iChannel0..iChannel3))"));
}

TEST(PortToolsManifestNearMiss, PassNameWithTrailingSpaceSuggestsImage) {
    ManifestFolder f;
    // "Image " is not "Image"; the one message says so (the missing Image is that typo).
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image ": {"source": "image.glsl"}}})")),
              f.line(R"(passes."Image ")",
                     R"(unknown pass (did you mean "Image"?) (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound))"));
}

TEST(PortToolsManifestNearMiss, LowerCaseBufferLetterIsRejectedWithTheRightName) {
    ManifestFolder f;
    // Pass names are exact ("Buffer a" is not accepted), but the message says which one was meant.
    EXPECT_EQ(
        errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "Buffer a": {"source": "buffer_a.glsl"}}})")),
        f.line(R"(passes."Buffer a")",
               R"(unknown pass (did you mean "Buffer A"?) (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound))"));
    // "Buffer E" is another index: no guess.
    EXPECT_EQ(
        errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}, "Buffer E": {"source": "buffer_a.glsl"}}})")),
        f.line(R"(passes."Buffer E")", "unknown pass (known: Buffer A, Buffer B, Buffer C, Buffer D, Cube A, Image, Sound)"));
}

TEST(PortToolsManifestNearMiss, MisspelledFilterAndWrapValues) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "filter": "neareest"}})"))),
              f.line(kImageCh0, R"(filter "neareest" (did you mean "nearest"?) is not one of nearest, linear, mipmap)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "filter": "blurry"}})"))),
              f.line(kImageCh0, R"(filter "blurry" is not one of nearest, linear, mipmap)"));
    EXPECT_EQ(errorOf(f.parse(imageWithChannels(R"({"iChannel0": {"buffer": "A", "wrap": "repaet"}})"))),
              f.line(kImageCh0, R"(wrap "repaet" (did you mean "repeat"?) is not one of clamp, repeat)"));
}

TEST(PortToolsManifestNearMiss, MisspelledTopLevelAndPassFields) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl"}}, "defualts": {}})")),
              f.line("", R"(unknown field "defualts" (did you mean "defaults"?) )"
                         R"((known: common, defaults, media, name, passes))"));
    EXPECT_EQ(errorOf(f.parse(R"({"passes": {"Image": {"source": "image.glsl", "chanels": []}}})")),
              f.line(R"(passes."Image")", R"(unknown field "chanels" (did you mean "channels"?) (known: channels, source))"));
}

// ---- 3. Stock media near misses -----------------------------------------------------------------

TEST(PortToolsStockMedia, OneHexCharacterOffIsANearMissOfGrayNoiseMedium) {
    const StockMediaInfo* near = nearStockMedia(kGrayNoiseOneTypo);
    ASSERT_NE(near, nullptr);
    EXPECT_EQ(near->name, "Gray Noise Medium");
    EXPECT_EQ(stockMediaPath(*near), kGrayNoisePath);
    EXPECT_EQ(findStockMedia(kGrayNoiseOneTypo), nullptr);  // not an exact reference
    // The bare hash, without the folder and extension, too.
    const std::string bareTypo = "0c7bf5fe9462d5bffbd11126e82908e39be3ce56220d900f633d58fb432e56f6";
    ASSERT_NE(nearStockMedia(bareTypo), nullptr);
    EXPECT_EQ(nearStockMedia(bareTypo)->name, "Gray Noise Medium");
}

TEST(PortToolsStockMedia, UpToThreeEditedHashCharactersAreANearMissFourAreNot) {
    std::string three = kGrayNoiseHash;
    three[0] = '1';
    three[10] = '0';
    three[20] = '0';
    ASSERT_EQ(editDistance(three, kGrayNoiseHash), 3u);
    ASSERT_NE(nearStockMedia("/media/a/" + three + ".png"), nullptr);
    EXPECT_EQ(nearStockMedia("/media/a/" + three + ".png")->name, "Gray Noise Medium");
    std::string four = three;
    four[30] = 'f';
    ASSERT_EQ(editDistance(four, kGrayNoiseHash), 4u);
    EXPECT_EQ(nearStockMedia("/media/a/" + four + ".png"), nullptr);
    // A dropped character is an edit too.
    EXPECT_NE(nearStockMedia("/media/a/" + kGrayNoiseHash.substr(1) + ".png"), nullptr);
}

TEST(PortToolsStockMedia, UpperCaseHashNearMissIsStillANearMiss) {
    auto upperCase = [](std::string text) {
        for (char& c : text)
            if (c >= 'a' && c <= 'f') c = static_cast<char>(c - 'a' + 'A');
        return text;
    };
    ASSERT_NE(findStockMedia("/media/a/" + upperCase(kGrayNoiseHash) + ".png"), nullptr);  // exact: case ignored
    std::string typo = kGrayNoiseHash;
    typo.back() = '6';
    const std::string upper = "/media/a/" + upperCase(typo) + ".png";
    const StockMediaInfo* near = nearStockMedia(upper);
    ASSERT_NE(near, nullptr) << upper;
    EXPECT_EQ(near->name, "Gray Noise Medium");
}

TEST(PortToolsStockMedia, LoaderRejectsAHashNearMissNamingTheTexture) {
    ManifestFolder f;
    auto result = f.parse(imageWithChannels(R"({"iChannel0": {"media": ")" + kGrayNoiseOneTypo + R"("}})"));
    EXPECT_EQ(errorOf(result), f.line(kImageCh0, "unknown stock media \"" + kGrayNoiseOneTypo +
                                                     "\" (did you mean \"Gray Noise Medium\", " + kGrayNoisePath +
                                                     "?)"));
    ASSERT_FALSE(result.ok());
    ASSERT_EQ(result.error().diagnostics.size(), 1u);
    EXPECT_EQ(result.error().first().code, Code::ManifestMediaNearMiss);
    EXPECT_EQ(result.error().first().pass, "Image");
    EXPECT_EQ(result.error().first().channel, 0);
}

TEST(PortToolsStockMedia, NameTypoSuggestsTheStockName) {
    const StockMediaInfo* near = nearStockMedia("Abstrac 3");
    ASSERT_NE(near, nullptr);
    EXPECT_EQ(near->name, "Abstract 3");
    ASSERT_NE(nearStockMedia("gray noise medum"), nullptr);
    EXPECT_EQ(nearStockMedia("gray noise medum")->name, "Gray Noise Medium");
    // Another index of a numbered name is not a typo.
    EXPECT_EQ(nearStockMedia("Abstract 4"), nullptr);

    ManifestFolder f;
    auto result = f.parse(imageWithChannels(R"({"iChannel0": {"media": "Abstrac 3"}})"));
    EXPECT_EQ(errorOf(result),
              f.line(kImageCh0, "unknown stock media \"Abstrac 3\" (did you mean \"Abstract 3\", " + kAbstract3Path + "?)"));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().first().code, Code::ManifestMediaNearMiss);
}

TEST(PortToolsStockMedia, GenuinelyUnknownIdStillLoads) {
    EXPECT_EQ(nearStockMedia("/media/a/0123abcd.png"), nullptr);
    EXPECT_EQ(findStockMedia("/media/a/0123abcd.png"), nullptr);
    ManifestFolder f;
    auto result = f.parse(imageWithChannels(R"({"iChannel0": {"media": "/media/a/0123abcd.png"}})"));
    ASSERT_TRUE(result.ok()) << result.error().text();
    const PassDesc* image = result->find(PassId::Image);
    ASSERT_NE(image, nullptr);
    EXPECT_EQ(image->channels[0].kind, ChannelKind::StockMedia);
    EXPECT_EQ(image->channels[0].media, "/media/a/0123abcd.png");
}

TEST(PortToolsStockMedia, NearMissWithAFileInMediaIsTheUsersOwnTexture) {
    ManifestFolder f;
    f.write("noise.png", "not decoded by the loader");
    auto result = f.parse(R"({"media": {")" + kGrayNoiseOneTypo + R"(": "noise.png"},
        "passes": {"Image": {"source": "image.glsl", "channels": {"iChannel0": {"media": ")" +
                          kGrayNoiseOneTypo + R"("}}}}})");
    ASSERT_TRUE(result.ok()) << result.error().text();
    EXPECT_EQ(result->mediaOverrides.at(kGrayNoiseOneTypo), f.dir / "noise.png");
}

TEST(PortToolsStockMedia, ExactReferencesAreNotNearMisses) {
    for (const std::string& exact : {kGrayNoisePath, kGrayNoiseHash, kGrayNoiseHash + ".png",
                                     std::string("Gray Noise Medium"), std::string("gray noise medium"),
                                     std::string("Abstract 3"), kAbstract3Path}) {
        EXPECT_EQ(nearStockMedia(exact), nullptr) << exact;
        EXPECT_NE(findStockMedia(exact), nullptr) << exact;
    }
    ManifestFolder f;
    auto result = f.parse(imageWithChannels(R"({"iChannel0": {"media": ")" + kGrayNoisePath + R"("},
                                                "iChannel1": {"media": "Abstract 3"}})"));
    ASSERT_TRUE(result.ok()) << result.error().text();
}

// ---- 4. The manifest's "defaults" block ---------------------------------------------------------

TEST(PortToolsManifestDefaults, SizeAsTextFpsAndFrames) {
    ManifestFolder f;
    auto result = f.parse(imageWithDefaults(R"({"size": "1280x720", "fps": 30, "frames": 600})"));
    ASSERT_TRUE(result.ok()) << result.error().text();
    const RunDefaults& d = result->runDefaults;
    EXPECT_EQ(d.width, std::optional<int>(1280));
    EXPECT_EQ(d.height, std::optional<int>(720));
    EXPECT_EQ(d.fps, std::optional<double>(30.0));
    EXPECT_EQ(d.frames, std::optional<int>(600));
}

TEST(PortToolsManifestDefaults, SizeAsArrayLeavesTheOthersUnset) {
    ManifestFolder f;
    auto result = f.parse(imageWithDefaults(R"({"size": [640, 360]})"));
    ASSERT_TRUE(result.ok()) << result.error().text();
    const RunDefaults& d = result->runDefaults;
    EXPECT_EQ(d.width, std::optional<int>(640));
    EXPECT_EQ(d.height, std::optional<int>(360));
    EXPECT_EQ(d.fps, std::nullopt);
    EXPECT_EQ(d.frames, std::nullopt);
}

TEST(PortToolsManifestDefaults, OtherAcceptedForms) {
    ManifestFolder f;
    auto result = f.parse(imageWithDefaults(R"({"size": "16384X1", "fps": 29.97, "frames": 1})"));
    ASSERT_TRUE(result.ok()) << result.error().text();
    EXPECT_EQ(result->runDefaults.width, std::optional<int>(16384));
    EXPECT_EQ(result->runDefaults.height, std::optional<int>(1));
    EXPECT_EQ(result->runDefaults.fps, std::optional<double>(29.97));
    EXPECT_EQ(result->runDefaults.frames, std::optional<int>(1));

    auto empty = f.parse(imageWithDefaults("{}"));
    ASSERT_TRUE(empty.ok()) << empty.error().text();
    EXPECT_EQ(empty->runDefaults.width, std::nullopt);
    EXPECT_EQ(empty->runDefaults.fps, std::nullopt);
}

TEST(PortToolsManifestDefaults, AbsentBlockLeavesEveryValueUnset) {
    ManifestFolder f;
    auto result = f.parse(R"({"passes": {"Image": {"source": "image.glsl"}}})");
    ASSERT_TRUE(result.ok()) << result.error().text();
    const RunDefaults& d = result->runDefaults;
    EXPECT_EQ(d.width, std::nullopt);
    EXPECT_EQ(d.height, std::nullopt);
    EXPECT_EQ(d.fps, std::nullopt);
    EXPECT_EQ(d.frames, std::nullopt);
}

TEST(PortToolsManifestDefaults, EachBadValueIsOneErrorAtItsField) {
    ManifestFolder f;
    const std::string size = R"(must be "WxH" or [W, H] with sides 1..16384, not )";
    const std::string fps = "must be a number of frames per second (0.001 .. 1000000), not ";
    const std::string frames = "must be a whole number of frames >= 1, not ";
    struct Case {
        std::string defaults, field, message;
    };
    const std::vector<Case> cases{
        {R"({"size": "0x5"})", "defaults.size", size + R"("0x5")"},
        {R"({"size": "big"})", "defaults.size", size + R"("big")"},
        {R"({"size": "1280x720px"})", "defaults.size", size + R"("1280x720px")"},
        {R"({"size": "1280*720"})", "defaults.size", size + R"("1280*720")"},
        {R"({"size": "16385x16"})", "defaults.size", size + R"("16385x16")"},
        {R"({"size": [1]})", "defaults.size", size + "[1]"},
        {R"({"size": [640, 360, 1]})", "defaults.size", size + "[640,360,1]"},
        {R"({"size": [640, -360]})", "defaults.size", size + "[640,-360]"},
        {R"({"size": [640.5, 360]})", "defaults.size", size + "[640.5,360]"},
        {R"({"size": 640})", "defaults.size", size + "640"},
        {R"({"fps": 0})", "defaults.fps", fps + "0"},
        {R"({"fps": -30})", "defaults.fps", fps + "-30"},
        {R"({"fps": "60"})", "defaults.fps", fps + R"("60")"},
        {R"({"fps": 2000000})", "defaults.fps", fps + "2000000"},
        {R"({"frames": 0})", "defaults.frames", frames + "0"},
        {R"({"frames": 1.5})", "defaults.frames", frames + "1.5"},
        {R"({"frames": -3})", "defaults.frames", frames + "-3"},
        {R"({"frames": "600"})", "defaults.frames", frames + R"("600")"},
        {R"({"frames": 3000000000})", "defaults.frames", frames + "3000000000"},
    };
    for (const Case& c : cases) {
        auto result = f.parse(imageWithDefaults(c.defaults));
        EXPECT_EQ(errorOf(result), f.line(c.field, c.message)) << c.defaults;
        if (result.ok()) continue;
        EXPECT_EQ(result.error().diagnostics.size(), 1u) << c.defaults;
        EXPECT_EQ(result.error().first().field, c.field) << c.defaults;
        EXPECT_EQ(result.error().first().code, Code::ManifestValue) << c.defaults;
    }
}

TEST(PortToolsManifestDefaults, UnknownKeyAndWrongShape) {
    ManifestFolder f;
    auto result = f.parse(imageWithDefaults(R"({"fsp": 60})"));
    EXPECT_EQ(errorOf(result),
              f.line("defaults", R"(unknown field "fsp" (did you mean "fps"?) (known: fps, frames, size))"));
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(result.error().first().code, Code::ManifestUnknownField);
    EXPECT_EQ(errorOf(f.parse(imageWithDefaults(R"({"frame": 60})"))),
              f.line("defaults", R"(unknown field "frame" (did you mean "frames"?) (known: fps, frames, size))"));
    EXPECT_EQ(errorOf(f.parse(imageWithDefaults(R"({"resolution": 60})"))),
              f.line("defaults", R"(unknown field "resolution" (known: fps, frames, size))"));
    EXPECT_EQ(errorOf(f.parse(imageWithDefaults(R"("1280x720")"))),
              f.line("defaults", R"(must be an object such as {"size": "1280x720", "fps": 60, "frames": 600})"));
}

TEST(PortToolsManifestDefaults, SeveralBadValuesAreReportedTogether) {
    ManifestFolder f;
    EXPECT_EQ(errorOf(f.parse(imageWithDefaults(R"({"size": "big", "fps": 0, "frames": 0})"))),
              f.line("defaults.size", R"(must be "WxH" or [W, H] with sides 1..16384, not "big")") + "\n" +
                  f.line("defaults.fps", "must be a number of frames per second (0.001 .. 1000000), not 0") + "\n" +
                  f.line("defaults.frames", "must be a whole number of frames >= 1, not 0"));
}

// ---- 5. Channels the code names ------------------------------------------------------------------

TEST(PortToolsChannelUse, FindsIChannelAndIChNames) {
    EXPECT_EQ(channelsNamed("fragColor = texture(iChannel0, uv) + texture(iChannel3, uv);"), named(1, 0, 0, 1));
    EXPECT_EQ(channelsNamed("vec4 a = texelFetch(iChannel1,ivec2(0),0);vec4 b=iChannel2.xyzw;"), named(0, 1, 1, 0));
    EXPECT_EQ(channelsNamed("iCh0 iCh1\niCh2\tiCh3"), named(1, 1, 1, 1));
    EXPECT_EQ(channelsNamed("iChannel2"), named(0, 0, 1, 0));  // at the very start and end
    EXPECT_EQ(channelsNamed(""), named(0, 0, 0, 0));
}

TEST(PortToolsChannelUse, IgnoresNamesInComments) {
    EXPECT_EQ(channelsNamed("// texture(iChannel0, uv)\nfloat x = 1.0;"), named(0, 0, 0, 0));
    EXPECT_EQ(channelsNamed("/* iChannel1\n iChannel2 */ texture(iChannel3, uv);"), named(0, 0, 0, 1));
    EXPECT_EQ(channelsNamed("float x; // iChannel1"), named(0, 0, 0, 0));  // comment at the end, no newline
    EXPECT_EQ(channelsNamed("float x; /* iChannel1"), named(0, 0, 0, 0));  // unterminated block comment
    EXPECT_EQ(channelsNamed("/* // */ iChannel1 // /* \n iChannel2"), named(0, 1, 1, 0));
    EXPECT_EQ(channelsNamed("x/*iChannel0*/iChannel1"), named(0, 1, 0, 0));
}

TEST(PortToolsChannelUse, IgnoresOtherIdentifiers) {
    EXPECT_EQ(channelsNamed("iChannelResolution[0].xy iChannelTime[1] iChannel4 myiChannel0 iChannel0x "
                            "iChannel_1 iCh4 iCh iChannel iChannel01 _iChannel2 iCh3a"),
              named(0, 0, 0, 0));
}

TEST(PortToolsChannelUse, OneWarningPerPassListingTheUnboundChannels) {
    ManifestDesc manifest;
    PassDesc a = passWithCode(PassId::BufferA,
                              "void mainImage(out vec4 c, in vec2 f) {\n"
                              "    c = texture(iChannel0, f) + texture(iChannel1, f) + texture(iChannel3, f);\n"
                              "}\n");
    bindBuffer(a, 0, 0);
    PassDesc b = passWithCode(PassId::BufferB, "void mainImage(out vec4 c, in vec2 f) { c = vec4(0); }\n");
    PassDesc image = passWithCode(PassId::Image, "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel2, f); }\n");
    bindBuffer(image, 0, 0);  // bound but not named: no warning for it
    manifest.passes = {a, b, image};

    const std::vector<Diagnostic> warnings = unboundChannelWarnings(manifest);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].severity, Severity::Warning);
    EXPECT_EQ(warnings[0].code, Code::ChannelUnbound);
    EXPECT_EQ(warnings[0].pass, "Buffer A");
    EXPECT_EQ(warnings[0].file, a.sourceName);
    EXPECT_EQ(warnings[0].channel, -1);
    EXPECT_EQ(warnings[0].message,
              "the code samples iChannel1, iChannel3, which have nothing bound and read as black "
              "(bind an input in the manifest's \"channels\")");
    EXPECT_EQ(warnings[1].severity, Severity::Warning);
    EXPECT_EQ(warnings[1].code, Code::ChannelUnbound);
    EXPECT_EQ(warnings[1].pass, "Image");
    EXPECT_EQ(warnings[1].file, image.sourceName);
    EXPECT_EQ(warnings[1].message,
              "the code samples iChannel2, which has nothing bound and reads as black "
              "(bind an input in the manifest's \"channels\")");
    EXPECT_EQ(formatDiagnostic(warnings[1]),
              image.sourceName + ": warning: Image: the code samples iChannel2, which has nothing bound and reads as "
                                 "black (bind an input in the manifest's \"channels\") [channel.unbound]");
}

TEST(PortToolsChannelUse, NoWarningWhenEveryNamedChannelIsBound) {
    ManifestDesc manifest;
    PassDesc image = passWithCode(PassId::Image,
                                  "// iChannel3 is only mentioned in a comment\n"
                                  "void mainImage(out vec4 c, in vec2 f) { c = texture(iChannel0, f) * iChannelTime[1]; }\n");
    bindBuffer(image, 0, 0);
    manifest.passes = {image};
    EXPECT_TRUE(unboundChannelWarnings(manifest).empty());

    // Any kind of input counts as bound.
    PassDesc keyboard = passWithCode(PassId::Image, "float k = texelFetch(iChannel1, ivec2(32, 0), 0).x;");
    keyboard.channels[1].kind = ChannelKind::Keyboard;
    manifest.passes = {keyboard};
    EXPECT_TRUE(unboundChannelWarnings(manifest).empty());

    EXPECT_TRUE(unboundChannelWarnings(ManifestDesc{}).empty());
}

// ---- 6. Gliding mouse moves ------------------------------------------------------------------

const std::string kDownThenGlide = R"([
    {"frame": 0, "type": "down", "x": 10, "y": 20},
    {"frame": 0, "type": "move", "to": {"frame": 10, "x": 110, "y": 20}}
])";

TEST(PortToolsGlide, ParsesTheEndOfTheGlide) {
    auto script = parseMouseScript(kDownThenGlide, "mouse.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    ASSERT_EQ(script->events.size(), 2u);
    const MouseScriptEvent& glide = script->events[1];
    EXPECT_EQ(glide.type, MouseScriptEvent::Type::Move);
    EXPECT_FALSE(glide.position.has_value());  // starts wherever the pointer is
    ASSERT_TRUE(glide.to.has_value());
    EXPECT_EQ(glide.to->end.clock, ScriptMoment::Clock::Frame);
    EXPECT_EQ(glide.to->end.frame, 10);
    EXPECT_EQ(glide.to->position, glm::vec2(110, 20));
    EXPECT_FALSE(script->events[0].to.has_value());
}

TEST(PortToolsGlide, MovesLinearlyOneMovePerFrameUntilItArrives) {
    const auto frames = playFrames(kDownThenGlide, 12);
    ASSERT_EQ(frames.size(), 13u);
    expectEvents(frames[0], {down(10, 20), move(10, 20)}, "frame 0");
    for (int frame = 1; frame <= 10; ++frame)
        expectEvents(frames[frame], {move(10.0f + 10.0f * frame, 20)}, "frame " + std::to_string(frame));
    expectEvents(frames[11], {}, "frame 11");
    expectEvents(frames[12], {}, "frame 12");
}

TEST(PortToolsGlide, FinishedOnlyOnceTheGlideArrives) {
    auto script = parseMouseScript(kDownThenGlide, "mouse.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    MouseScriptPlayer player(std::move(*script));
    EXPECT_FALSE(player.finished());
    std::vector<InputEvent> events;
    for (int frame = 0; frame <= 12; ++frame) {
        player.eventsBeforeFrame(frame, frame / 60.0, events);
        EXPECT_EQ(player.finished(), frame >= 10) << "after frame " << frame;
    }
}

TEST(PortToolsGlide, StartsFromThePointersLastScriptedPosition) {
    const auto frames = playFrames(R"([
        {"frame": 0, "type": "down", "x": 10, "y": 20},
        {"frame": 2, "type": "move", "x": 50, "y": 60},
        {"frame": 4, "type": "move", "to": {"frame": 8, "x": 90, "y": 20}},
        {"frame": 9, "type": "move", "to": {"frame": 11, "x": 90, "y": 60}},
        {"frame": 12, "type": "up"}
    ])", 13);
    expectEvents(frames[2], {move(50, 60)}, "frame 2");
    expectEvents(frames[3], {}, "frame 3");
    expectEvents(frames[4], {move(50, 60)}, "frame 4");  // from the last "move"
    expectEvents(frames[5], {move(60, 50)}, "frame 5");
    expectEvents(frames[6], {move(70, 40)}, "frame 6");
    expectEvents(frames[8], {move(90, 20)}, "frame 8");
    // The second glide starts where the first one arrived.
    expectEvents(frames[9], {move(90, 20)}, "frame 9");
    expectEvents(frames[10], {move(90, 40)}, "frame 10");
    expectEvents(frames[11], {move(90, 60)}, "frame 11");
    expectEvents(frames[12], {kUp}, "frame 12");
    expectEvents(frames[13], {}, "frame 13");
}

TEST(PortToolsGlide, ExplicitXYIsTheStartOfTheGlide) {
    const auto frames = playFrames(R"([
        {"frame": 0, "type": "down", "x": 10, "y": 20},
        {"frame": 0, "type": "move", "x": 0, "y": 0, "to": {"frame": 4, "x": 40, "y": 80}}
    ])", 5);
    expectEvents(frames[0], {down(10, 20), move(0, 0)}, "frame 0");
    expectEvents(frames[1], {move(10, 20)}, "frame 1");
    expectEvents(frames[2], {move(20, 40)}, "frame 2");
    expectEvents(frames[3], {move(30, 60)}, "frame 3");
    expectEvents(frames[4], {move(40, 80)}, "frame 4");
    expectEvents(frames[5], {}, "frame 5");
}

TEST(PortToolsGlide, TimeGlideInterpolatesByITime) {
    // 4 frames per second: iTime = 0, 0.25, 0.5, ...
    const auto frames = playFrames(R"([
        {"time": 0, "type": "down", "x": 0, "y": 0},
        {"time": 0.5, "type": "move", "to": {"time": 1.5, "x": 100, "y": 50}}
    ])", 7, 4.0);
    expectEvents(frames[0], {down(0, 0)}, "frame 0");
    expectEvents(frames[1], {}, "frame 1");
    expectEvents(frames[2], {move(0, 0)}, "frame 2 (0.5 s)");
    expectEvents(frames[3], {move(25, 12.5f)}, "frame 3 (0.75 s)");
    expectEvents(frames[4], {move(50, 25)}, "frame 4 (1.0 s)");
    expectEvents(frames[5], {move(75, 37.5f)}, "frame 5 (1.25 s)");
    expectEvents(frames[6], {move(100, 50)}, "frame 6 (1.5 s)");
    expectEvents(frames[7], {}, "frame 7");
}

TEST(PortToolsGlide, GlideThatFiresLateIsWhereItWouldHaveBeen) {
    auto script = parseMouseScript(kDownThenGlide, "mouse.json");
    ASSERT_TRUE(script.ok()) << script.error().text();
    MouseScriptPlayer player(std::move(*script));
    std::vector<InputEvent> events;
    player.eventsBeforeFrame(5, 5 / 60.0, events);  // the run starts at frame 5
    expectEvents(events, {down(10, 20), move(60, 20)}, "frame 5");
    events.clear();
    player.eventsBeforeFrame(20, 20 / 60.0, events);  // jumps past the end
    expectEvents(events, {move(110, 20)}, "frame 20");
    EXPECT_TRUE(player.finished());
}

TEST(PortToolsGlide, ChainedGlidesMeetWhereTheFirstArrives) {
    // A drag in two segments, like shadertoys/ripple-pool/drag.json: (0,0) -> (40,0) on frame 4 ->
    // (40,40) on frame 8.
    const auto frames = playFrames(R"([
        {"frame": 0, "type": "down", "x": 0, "y": 0},
        {"frame": 0, "type": "move", "to": {"frame": 4, "x": 40, "y": 0}},
        {"frame": 4, "type": "move", "to": {"frame": 8, "x": 40, "y": 40}}
    ])", 9);
    ASSERT_FALSE(frames[4].empty());
    // The frame of the joint sees the pointer at the joint...
    EXPECT_NEAR(frames[4].back().x, 40, 1e-4) << describe(frames[4]);
    EXPECT_NEAR(frames[4].back().y, 0, 1e-4) << describe(frames[4]);
    // ... and the second segment runs from there.
    expectEvents(frames[5], {move(40, 10)}, "frame 5");
    expectEvents(frames[6], {move(40, 20)}, "frame 6");
    expectEvents(frames[7], {move(40, 30)}, "frame 7");
    expectEvents(frames[8], {move(40, 40)}, "frame 8");
    expectEvents(frames[9], {}, "frame 9");
}

TEST(PortToolsGlide, ErrorsNameTheEvent) {
    const std::string first = R"([{"frame": 0, "type": "down", "x": 1, "y": 2}, )";
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "down", "x": 1, "y": 2, "to": {"frame": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" is only for \"move\" events");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "up", "to": {"frame": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" is only for \"move\" events");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": {"time": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" must use the event's own clock (\"frame\")");
    EXPECT_EQ(mouseError(first + R"({"time": 1, "type": "move", "to": {"frame": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" must use the event's own clock (\"time\")");
    EXPECT_EQ(mouseError(first + R"({"frame": 10, "type": "move", "to": {"frame": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" must end after the event starts");
    EXPECT_EQ(mouseError(first + R"({"frame": 10, "type": "move", "to": {"frame": 10, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" must end after the event starts");
    EXPECT_EQ(mouseError(first + R"({"time": 2, "type": "move", "to": {"time": 1.5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\" must end after the event starts");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": {"frame": 5, "x": 0}}])"),
              "mouse.json: event 1: \"to\": \"y\" is missing");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": {"frame": 5, "x": 0, "y": 0, "z": 1}}])"),
              "mouse.json: event 1: \"to\": unknown field \"z\" (known: frame, time, x, y)");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": {"x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"to\": \"frame\" or \"time\" is missing");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": {"frame": 5, "x": "a", "y": 0}}])"),
              "mouse.json: event 1: \"to\": \"x\" must be a number of pixels within +-1000000, got string \"a\"");
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "to": [5, 0, 0]}])"),
              "mouse.json: event 1: \"to\" must be an object such as {\"frame\": 60, \"x\": 10, \"y\": 20}, got array");
    // The start of a glide is "x" and "y" together or neither.
    EXPECT_EQ(mouseError(first + R"({"frame": 1, "type": "move", "x": 3, "to": {"frame": 5, "x": 0, "y": 0}}])"),
              "mouse.json: event 1: \"y\" is missing");
}

// ---- 7. Starter folders --------------------------------------------------------------------

TEST(PortToolsStarterLayout, ImageOnly) {
    auto layout = parseStarterLayout("image");
    ASSERT_TRUE(layout.ok()) << layout.error().text();
    EXPECT_FALSE(layout->common);
    for (int b = 0; b < kBufferCount; ++b) EXPECT_FALSE(layout->buffers[b]) << b;
}

TEST(PortToolsStarterLayout, BuffersIsBufferAAndImage) {
    for (const char* text : {"buffers", "buffer", " Buffers "}) {
        auto layout = parseStarterLayout(text);
        ASSERT_TRUE(layout.ok()) << text << ": " << layout.error().text();
        EXPECT_FALSE(layout->common) << text;
        EXPECT_TRUE(layout->buffers[0]) << text;
        EXPECT_FALSE(layout->buffers[1]) << text;
        EXPECT_FALSE(layout->buffers[2]) << text;
        EXPECT_FALSE(layout->buffers[3]) << text;
    }
}

TEST(PortToolsStarterLayout, CommaLists) {
    auto withCommon = parseStarterLayout("common,a,image");
    ASSERT_TRUE(withCommon.ok()) << withCommon.error().text();
    EXPECT_TRUE(withCommon->common);
    EXPECT_TRUE(withCommon->buffers[0]);
    EXPECT_FALSE(withCommon->buffers[1]);

    auto bufferB = parseStarterLayout("Buffer B, image");
    ASSERT_TRUE(bufferB.ok()) << bufferB.error().text();
    EXPECT_FALSE(bufferB->common);
    EXPECT_FALSE(bufferB->buffers[0]);
    EXPECT_TRUE(bufferB->buffers[1]);
    EXPECT_FALSE(bufferB->buffers[2]);
    EXPECT_FALSE(bufferB->buffers[3]);

    auto many = parseStarterLayout("A, c,D");  // Image is always part of it
    ASSERT_TRUE(many.ok()) << many.error().text();
    EXPECT_TRUE(many->buffers[0]);
    EXPECT_FALSE(many->buffers[1]);
    EXPECT_TRUE(many->buffers[2]);
    EXPECT_TRUE(many->buffers[3]);
}

TEST(PortToolsStarterLayout, UnknownWordIsNamed) {
    auto layout = parseStarterLayout("a,e");
    ASSERT_FALSE(layout.ok());
    EXPECT_EQ(layout.error().first().message,
              "--passes: \"e\" is not a pass (use image, buffers, or a comma list of common, a, b, c, d, image)");
    EXPECT_EQ(layout.error().first().code, Code::UsagePasses);
    auto other = parseStarterLayout("image,sound");
    ASSERT_FALSE(other.ok());
    EXPECT_EQ(other.error().first().message,
              "--passes: \"sound\" is not a pass (use image, buffers, or a comma list of common, a, b, c, d, image)");
}

namespace {
// Writes the starter for `layoutText` into a folder "toy" and loads it back.
struct StarterFolder {
    toyhost::testing::TestFolder root;
    fs::path dir = root.path / "toy";
    Result<ManifestDesc> writeAndLoad(const std::string& layoutText) {
        auto layout = parseStarterLayout(layoutText);
        EXPECT_TRUE(layout.ok());
        if (!layout.ok()) return layout.error();
        Status written = writeStarter(dir, *layout, false);
        EXPECT_TRUE(written.ok()) << (written.ok() ? "" : written.error().text());
        if (!written.ok()) return written.error();
        return loadManifest(dir);
    }
};
}  // namespace

TEST(PortToolsStarter, ImageLayoutLoads) {
    StarterFolder s;
    auto manifest = s.writeAndLoad("image");
    ASSERT_TRUE(manifest.ok()) << manifest.error().text();
    EXPECT_EQ(manifest->name, "toy");
    EXPECT_EQ(passIds(*manifest), std::vector<PassId>{PassId::Image});
    EXPECT_FALSE(manifest->commonSource.has_value());
    for (int c = 0; c < kChannelCount; ++c) EXPECT_EQ(manifest->passes[0].channels[c].kind, ChannelKind::None) << c;
    EXPECT_EQ(manifest->passes[0].source, s.dir / "image.glsl");
    EXPECT_NE(manifest->passes[0].code.find("void mainImage( out vec4 fragColor, in vec2 fragCoord )"), std::string::npos);
    EXPECT_TRUE(unboundChannelWarnings(*manifest).empty());
    EXPECT_EQ(folderContents(s.dir).size(), 3u);  // manifest.json, image.glsl, README.md
}

TEST(PortToolsStarter, BuffersLayoutIsBufferAFeedingItselfAndImage) {
    StarterFolder s;
    auto manifest = s.writeAndLoad("buffers");
    ASSERT_TRUE(manifest.ok()) << manifest.error().text();
    ASSERT_EQ(passIds(*manifest), (std::vector<PassId>{PassId::BufferA, PassId::Image}));
    const ChannelDesc& self = manifest->passes[0].channels[0];
    EXPECT_EQ(self.kind, ChannelKind::Buffer);
    EXPECT_EQ(self.buffer, 0);
    const ChannelDesc& shown = manifest->passes[1].channels[0];
    EXPECT_EQ(shown.kind, ChannelKind::Buffer);
    EXPECT_EQ(shown.buffer, 0);
    for (int c = 1; c < kChannelCount; ++c) {
        EXPECT_EQ(manifest->passes[0].channels[c].kind, ChannelKind::None) << c;
        EXPECT_EQ(manifest->passes[1].channels[c].kind, ChannelKind::None) << c;
    }
    EXPECT_EQ(manifest->passes[0].source, s.dir / "buffer_a.glsl");
    EXPECT_TRUE(unboundChannelWarnings(*manifest).empty());
}

TEST(PortToolsStarter, CommonBufferAndImageLayoutLoads) {
    StarterFolder s;
    auto manifest = s.writeAndLoad("common,a,image");
    ASSERT_TRUE(manifest.ok()) << manifest.error().text();
    EXPECT_EQ(passIds(*manifest), (std::vector<PassId>{PassId::BufferA, PassId::Image}));
    ASSERT_TRUE(manifest->commonSource.has_value());
    EXPECT_EQ(*manifest->commonSource, s.dir / "common.glsl");
    EXPECT_EQ(manifest->passes[1].channels[0].kind, ChannelKind::Buffer);
    EXPECT_TRUE(fs::is_regular_file(s.dir / "common.glsl"));
    EXPECT_TRUE(unboundChannelWarnings(*manifest).empty());
}

TEST(PortToolsStarter, BufferBLayoutLoads) {
    StarterFolder s;
    auto manifest = s.writeAndLoad("Buffer B, image");
    ASSERT_TRUE(manifest.ok()) << manifest.error().text();
    EXPECT_EQ(passIds(*manifest), (std::vector<PassId>{PassId::BufferB, PassId::Image}));
    EXPECT_FALSE(manifest->commonSource.has_value());
    // Without Buffer A nothing is wired: both passes hold the site's default code.
    for (const PassDesc& pass : manifest->passes)
        for (int c = 0; c < kChannelCount; ++c) EXPECT_EQ(pass.channels[c].kind, ChannelKind::None) << c;
    EXPECT_TRUE(fs::is_regular_file(s.dir / "buffer_b.glsl"));
    EXPECT_FALSE(fs::exists(s.dir / "buffer_a.glsl"));
    EXPECT_TRUE(unboundChannelWarnings(*manifest).empty());
}

TEST(PortToolsStarter, ReadmeNamesTheFolder) {
    StarterFolder s;
    ASSERT_TRUE(s.writeAndLoad("buffers").ok());
    ASSERT_TRUE(fs::is_regular_file(s.dir / "README.md"));
    const std::string readme = readFile(s.dir / "README.md");
    EXPECT_EQ(readme.rfind("# toy\n", 0), 0u) << readme;
    EXPECT_NE(readme.find("toyhost run toy "), std::string::npos) << readme;
    EXPECT_NE(readme.find("- `buffer_a.glsl`: Buffer A (reads its own previous frame)\n"), std::string::npos) << readme;
    EXPECT_NE(readme.find("- `image.glsl`: Image (shows Buffer A)\n"), std::string::npos) << readme;
    EXPECT_NE(readme.find("copy them from the site's settings under each iChannel"), std::string::npos) << readme;
}

TEST(PortToolsStarter, SecondWriteWithoutOverwriteFailsAndWritesNothing) {
    StarterFolder s;
    ASSERT_TRUE(s.writeAndLoad("buffers").ok());
    // The user edits a pass, then runs `toyhost new` again by mistake.
    s.root.write("toy/image.glsl", "// my own work\n");
    const auto before = folderContents(s.dir);

    auto layout = parseStarterLayout("buffers");
    ASSERT_TRUE(layout.ok());
    Status again = writeStarter(s.dir, *layout, false);
    ASSERT_FALSE(again.ok());
    EXPECT_EQ(again.error().first().code, Code::IoExists);
    EXPECT_EQ(again.error().first().file, (s.dir / "manifest.json").string());
    EXPECT_EQ(again.error().first().message, "already exists (use --force to overwrite)");
    EXPECT_EQ(folderContents(s.dir), before);

    // With overwrite it is written afresh.
    ASSERT_TRUE(writeStarter(s.dir, *layout, true).ok());
    EXPECT_NE(readFile(s.dir / "image.glsl"), "// my own work\n");
    EXPECT_EQ(folderContents(s.dir).size(), before.size());
}

// Every channel the starter writes spells out its sampler (filter, wrap, and vflip where the kind
// takes it), so an author who pastes code sees what to copy from the site's channel settings; the
// values are the loader's defaults, so the folder runs exactly as it would without them.
TEST(PortToolsStarter, EveryChannelWrittenSpellsOutTheLoadersDefaultSampler) {
    for (const char* layout : {"image", "buffers", "common,a,b,c,d,image"}) {
        StarterFolder s;
        auto manifest = s.writeAndLoad(layout);
        ASSERT_TRUE(manifest.ok()) << layout << ": " << manifest.error().text();
        nlohmann::json json = nlohmann::json::parse(readFile(s.dir / "manifest.json"));
        int written = 0;
        for (const PassDesc& pass : manifest->passes)
            for (int c = 0; c < kChannelCount; ++c) {
                const ChannelDesc& channel = pass.channels[c];
                if (channel.kind == ChannelKind::None) continue;
                ++written;
                const nlohmann::json& object = json["passes"][passName(pass.id)]["channels"]["iChannel" + std::to_string(c)];
                const SamplerDesc defaults = defaultSampler(channel.kind);
                EXPECT_EQ(object.value("filter", ""), filterName(defaults.filter)) << layout << " " << object.dump();
                EXPECT_EQ(object.value("wrap", ""), wrapName(defaults.wrap)) << layout << " " << object.dump();
                EXPECT_EQ(object.contains("vflip"), takesVflip(channel.kind)) << layout << " " << object.dump();
                if (takesVflip(channel.kind)) EXPECT_EQ(object["vflip"].get<bool>(), defaults.vflip) << layout;
                EXPECT_EQ(channel.sampler.filter, defaults.filter);
                EXPECT_EQ(channel.sampler.wrap, defaults.wrap);
                EXPECT_EQ(channel.sampler.vflip, defaults.vflip);
            }
        EXPECT_EQ(written, std::string(layout) == "image" ? 0 : 2) << layout;
        // Without the spelled-out settings the loader gives the same channels.
        for (auto& [name, body] : json["passes"].items())
            if (body.contains("channels"))
                for (auto& [channelName, object] : body["channels"].items())
                    for (const char* key : {"filter", "wrap", "vflip"}) object.erase(key);
        s.root.write("toy/manifest.json", json.dump(2));
        auto bare = loadManifest(s.dir);
        ASSERT_TRUE(bare.ok()) << bare.error().text();
        ASSERT_EQ(bare->passes.size(), manifest->passes.size());
        for (std::size_t p = 0; p < bare->passes.size(); ++p)
            for (int c = 0; c < kChannelCount; ++c) {
                const SamplerDesc& a = bare->passes[p].channels[c].sampler;
                const SamplerDesc& b = manifest->passes[p].channels[c].sampler;
                EXPECT_TRUE(a.filter == b.filter && a.wrap == b.wrap && a.vflip == b.vflip) << layout << " pass " << p << " " << c;
            }
    }
}

TEST(PortToolsStarter, RefusesAFolderHoldingOneOfItsPassFiles) {
    StarterFolder s;
    s.root.write("toy/image.glsl", "// my own work\n");
    auto layout = parseStarterLayout("image");
    ASSERT_TRUE(layout.ok());
    Status written = writeStarter(s.dir, *layout, false);
    ASSERT_FALSE(written.ok());
    EXPECT_EQ(written.error().first().code, Code::IoExists);
    EXPECT_EQ(written.error().first().file, (s.dir / "image.glsl").string());
    EXPECT_EQ(folderContents(s.dir), (std::map<std::string, std::string>{{"image.glsl", "// my own work\n"}}));
}

TEST(PortToolsStarter, FolderNamedWithATrailingSlash) {
    toyhost::testing::TestFolder root;
    auto layout = parseStarterLayout("image");
    ASSERT_TRUE(layout.ok());
    ASSERT_TRUE(writeStarter(root.path / "slashed" / "", *layout, false).ok());
    auto manifest = loadManifest(root.path / "slashed");
    ASSERT_TRUE(manifest.ok()) << manifest.error().text();
    EXPECT_EQ(manifest->name, "slashed");
    EXPECT_EQ(readFile(root.path / "slashed" / "README.md").rfind("# slashed\n", 0), 0u);
}
