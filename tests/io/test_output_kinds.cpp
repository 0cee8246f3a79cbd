// OutputKinds: the one table of what --out writes. Each kind's extensions parse back to it, the
// facts of PNG, EXR, a video and the raw stream are the ones the session relies on, and the sink
// made for a kind takes its frames in order exactly when the kind is streamed. (In the io tests,
// not the pure unit tests: the capture module links the image codecs.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "capture/OutputKinds.h"
#include "capture/OutputPattern.h"
#include "capture/OutputSink.h"
#include "core/ChildProcess.h"

using namespace toyhost;

namespace {

const OutputKind& kindOf(const std::string& pattern) {
    Result<OutputPattern> parsed = OutputPattern::parse(pattern);
    EXPECT_TRUE(parsed.ok()) << pattern;
    return parsed.ok() ? parsed->kind() : outputKinds().front();
}

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
    return text;
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

}  // namespace

TEST(OutputKinds, EveryExtensionParsesBackToItsKind) {
    std::set<std::string> seen;
    for (const OutputKind& kind : outputKinds()) {
        EXPECT_EQ(kind.toFile, !kind.extensions.empty()) << kind.name;
        for (const char* ext : kind.extensions) {
            EXPECT_TRUE(seen.insert(ext).second) << ext << " belongs to two kinds";
            EXPECT_EQ(ext[0], '.') << ext;
            EXPECT_EQ(lower(ext), ext) << "the parser looks extensions up in lower case";
            EXPECT_EQ(outputKindOfExtension(ext), &kind) << ext;
            EXPECT_EQ(&kindOf(std::string("out/a") + ext), &kind) << ext;
            EXPECT_EQ(&kindOf("a" + upper(ext)), &kind) << ext;
            if (kind.filePerFrame()) {
                EXPECT_EQ(&kindOf(std::string("f_%04d") + ext), &kind) << ext;
            }
        }
        EXPECT_EQ(&outputKind(kind.format), &kind) << kind.name;
    }
    EXPECT_EQ(outputKindOfExtension(".jpg"), nullptr);
    EXPECT_EQ(outputKindOfExtension(""), nullptr);
    EXPECT_FALSE(kindOf(kRawStreamPattern).toFile);
}

TEST(OutputKinds, FactsOfPngExrVideoAndRawStream) {
    const OutputKind& png = kindOf("f_%04d.png");
    EXPECT_TRUE(png.toFile && png.filePerFrame() && png.tiles);
    EXPECT_FALSE(png.streamed || png.floats || png.exrSettings || png.ffmpeg || png.fixedRate || png.soundTrack);

    const OutputKind& exr = kindOf("f_%04d.exr");
    EXPECT_TRUE(exr.toFile && exr.filePerFrame() && exr.tiles && exr.floats && exr.exrSettings);
    EXPECT_FALSE(exr.streamed || exr.ffmpeg || exr.fixedRate || exr.soundTrack);

    const OutputKind& mp4 = kindOf("take.mp4");
    EXPECT_TRUE(mp4.toFile && mp4.streamed && mp4.oneFile() && mp4.ffmpeg && mp4.fixedRate && mp4.soundTrack);
    EXPECT_FALSE(mp4.floats || mp4.exrSettings || mp4.tiles || mp4.filePerFrame());
    EXPECT_STREQ(mp4.name, "video");

    const OutputKind& raw = kindOf("-");
    EXPECT_TRUE(raw.streamed);
    EXPECT_FALSE(raw.toFile || raw.oneFile() || raw.filePerFrame() || raw.floats || raw.tiles || raw.ffmpeg ||
                 raw.soundTrack);
}

TEST(OutputKinds, MessagesListTheTable) {
    EXPECT_EQ(outputKindsOffered(), ".png, .exr, a video .mp4/.webm/.mov/.mkv, or - for raw RGBA on stdout");
    EXPECT_EQ(extensionsWhere(&OutputKind::soundTrack), ".mp4, .webm, .mov, .mkv");
    EXPECT_EQ(extensionsWhere(&OutputKind::ffmpeg), ".mp4, .webm, .mov, .mkv");
    EXPECT_EQ(extensionsWhere(&OutputKind::floats), ".exr");
    EXPECT_EQ(tiledKindNames(), "PNG or EXR");
}

TEST(OutputKinds, SinkIsOrderedExactlyWhenTheKindIsStreamed) {
    const bool ffmpeg = findExecutable("ffmpeg").has_value();
    int checked = 0;
    for (const char* pattern : {"f_%04d.png", "f_%04d.exr", "-", "take.mp4", "take.webm"}) {
        OutputSinkRequest request;
        request.width = 64;
        request.height = 36;
        request.output = *OutputPattern::parse(std::string(pattern) == "-" ? pattern
                                               : (testing::TempDir() + "/kinds_" + pattern));
        if (request.output.kind().ffmpeg && !ffmpeg) continue;
        Result<OutputSink> made = makeOutputSink(request);
        ASSERT_TRUE(made.ok()) << pattern << ": " << made.error().text();
        EXPECT_EQ(made->sink->ordered(), request.output.kind().streamed) << pattern;
        EXPECT_EQ(made->videoEncoder.empty(), !request.output.kind().ffmpeg) << pattern;
        made->sink->discard();
        ++checked;
    }
    EXPECT_GE(checked, 3);
}
