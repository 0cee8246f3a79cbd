// OutputPattern: the `--out` argument's frame-number placeholder, "%%", and the format chosen from
// the extension.
#include <gtest/gtest.h>

#include <string>

#include "capture/OutputPattern.h"

using namespace toyhost;

namespace {

OutputPattern parseOk(const std::string& text) {
    Result<OutputPattern> p = OutputPattern::parse(text);
    EXPECT_TRUE(p.ok()) << text << ": " << (p.ok() ? "" : p.error().text());
    return p.ok() ? p.value() : *OutputPattern::parse("unparsed.png");
}

std::string errorOf(const std::string& text) {
    Result<OutputPattern> p = OutputPattern::parse(text);
    EXPECT_FALSE(p.ok()) << text << " was accepted";
    return p.ok() ? std::string("<accepted>") : p.error().first().message;
}

const std::string kFormats = "(use .png, .exr, a video .mp4/.webm/.mov/.mkv, or - for raw RGBA on stdout)";
const std::string kPlaceholderError = "only %d or %0Nd (N <= 12) may stand for the frame number";

}  // namespace

TEST(OutputPattern, PlainD) {
    const OutputPattern p = parseOk("out/frame_%d.png");
    EXPECT_TRUE(p.numbered());
    EXPECT_EQ(p.format(), OutputFormat::Png);
    EXPECT_EQ(p.text(), "out/frame_%d.png");
    EXPECT_EQ(p.pathFor(0), "out/frame_0.png");
    EXPECT_EQ(p.pathFor(7), "out/frame_7.png");
    EXPECT_EQ(p.pathFor(1234567), "out/frame_1234567.png");
}

TEST(OutputPattern, ZeroPadded) {
    const OutputPattern p = parseOk("frames/%04d.exr");
    EXPECT_TRUE(p.numbered());
    EXPECT_EQ(p.format(), OutputFormat::Exr);
    EXPECT_EQ(p.pathFor(0), "frames/0000.exr");
    EXPECT_EQ(p.pathFor(7), "frames/0007.exr");
    EXPECT_EQ(p.pathFor(42), "frames/0042.exr");
    EXPECT_EQ(p.pathFor(9999), "frames/9999.exr");
    // Numbers wider than the pad are written in full, like printf.
    EXPECT_EQ(p.pathFor(12345), "frames/12345.exr");
    EXPECT_EQ(p.pathFor(1000000), "frames/1000000.exr");

    EXPECT_EQ(parseOk("f%01d.png").pathFor(5), "f5.png");
    EXPECT_EQ(parseOk("f%01d.png").pathFor(50), "f50.png");
    EXPECT_EQ(parseOk("f%012d.png").pathFor(3), "f000000000003.png");
    EXPECT_EQ(parseOk("f%00d.png").pathFor(3), "f3.png");
}

TEST(OutputPattern, PercentPercentIsALiteralPercent) {
    const OutputPattern p = parseOk("100%%_%03d.png");
    EXPECT_TRUE(p.numbered());
    EXPECT_EQ(p.pathFor(4), "100%_004.png");
    const OutputPattern fixed = parseOk("50%%.png");
    EXPECT_FALSE(fixed.numbered());
    EXPECT_EQ(fixed.pathFor(0), "50%.png");
    EXPECT_EQ(fixed.pathFor(3), "50%.png");
    // "%%d" is a literal "%d", not a placeholder.
    const OutputPattern literal = parseOk("a%%d.png");
    EXPECT_FALSE(literal.numbered());
    EXPECT_EQ(literal.pathFor(9), "a%d.png");
}

TEST(OutputPattern, NoPlaceholderWritesOneFile) {
    const OutputPattern p = parseOk("shots/final.png");
    EXPECT_FALSE(p.numbered());
    EXPECT_EQ(p.format(), OutputFormat::Png);
    EXPECT_EQ(p.pathFor(0), "shots/final.png");
    EXPECT_EQ(p.pathFor(59), "shots/final.png");
}

TEST(OutputPattern, ExtensionPicksFormatCaseInsensitively) {
    EXPECT_EQ(parseOk("a.png").format(), OutputFormat::Png);
    EXPECT_EQ(parseOk("a.PNG").format(), OutputFormat::Png);
    EXPECT_EQ(parseOk("a_%d.Png").format(), OutputFormat::Png);
    EXPECT_EQ(parseOk("a.exr").format(), OutputFormat::Exr);
    EXPECT_EQ(parseOk("a_%02d.EXR").format(), OutputFormat::Exr);
    EXPECT_EQ(parseOk("dir.v2/a.exr").format(), OutputFormat::Exr);
    // The path keeps the case as written.
    EXPECT_EQ(parseOk("A_%02d.PNG").pathFor(3), "A_03.PNG");
}

TEST(OutputPattern, TwoPlaceholdersAreAnError) {
    EXPECT_EQ(errorOf("run%d/frame%04d.png"), "--out run%d/frame%04d.png: the frame number may appear only once");
    EXPECT_EQ(errorOf("%d%d.png"), "--out %d%d.png: the frame number may appear only once");
}

TEST(OutputPattern, OnlyDAndZeroPaddedDAreAccepted) {
    for (const char* bad : {"f%5d.png", "f%s.png", "f%x.png", "f%-4d.png", "f%+d.png", "f%4.png", "f%013d.png",
                            "f%09999999999d.png", "f%9999999999", // widths beyond int (a fuzz finding)
                            "f%lld.png", "f.png%", "f%"}) {
        EXPECT_EQ(errorOf(bad), "--out " + std::string(bad) + ": " + kPlaceholderError) << bad;
    }
}

TEST(OutputPattern, UnsupportedExtension) {
    EXPECT_EQ(errorOf("frame_%04d.jpg"), "--out frame_%04d.jpg: unsupported format \".jpg\" " + kFormats);
    EXPECT_EQ(errorOf("frame.tiff"), "--out frame.tiff: unsupported format \".tiff\" " + kFormats);
    EXPECT_EQ(errorOf("frame"), "--out frame: unsupported format \"\" " + kFormats);
    EXPECT_EQ(errorOf("frame_%04d"), "--out frame_%04d: unsupported format \"\" " + kFormats);
    EXPECT_EQ(errorOf("frame.png.bak"), "--out frame.png.bak: unsupported format \".bak\" " + kFormats);
    // The extension belongs to the part after the placeholder: one before it does not count.
    EXPECT_EQ(errorOf("frame.png%d"), "--out frame.png%d: unsupported format \"\" " + kFormats);
}

TEST(OutputPattern, ExtensionWhenThePlaceholderIsInTheDirectory) {
    const OutputPattern p = parseOk("run_%03d/frame.exr");
    EXPECT_TRUE(p.numbered());
    EXPECT_EQ(p.format(), OutputFormat::Exr);
    EXPECT_EQ(p.pathFor(12), "run_012/frame.exr");
    // A dot in a directory is not an extension.
    EXPECT_EQ(errorOf("run_%d.png/frame"), "--out run_%d.png/frame: unsupported format \"\" " + kFormats);
    EXPECT_EQ(errorOf("out.png/frame"), "--out out.png/frame: unsupported format \"\" " + kFormats);
    EXPECT_EQ(errorOf("out.png/%d"), "--out out.png/%d: unsupported format \"\" " + kFormats);
    EXPECT_EQ(parseOk("out.d/%d.png").pathFor(1), "out.d/1.png");
}

TEST(OutputPattern, VideoAndRawStream) {
    const OutputPattern mp4 = parseOk("out/movie.MP4");
    EXPECT_EQ(mp4.format(), OutputFormat::Video);
    EXPECT_TRUE(mp4.streamed());
    EXPECT_EQ(mp4.extension(), ".mp4");
    EXPECT_EQ(mp4.pathFor(7), "out/movie.MP4");
    EXPECT_EQ(parseOk("a.webm").format(), OutputFormat::Video);
    EXPECT_EQ(parseOk("a.mov").format(), OutputFormat::Video);
    EXPECT_EQ(parseOk("a.mkv").format(), OutputFormat::Video);
    EXPECT_EQ(errorOf("movie_%04d.mp4"), "--out movie_%04d.mp4: a video is one file: remove the frame number placeholder");
    const OutputPattern raw = parseOk("-");
    EXPECT_EQ(raw.format(), OutputFormat::RawStream);
    EXPECT_TRUE(raw.streamed());
    EXPECT_FALSE(raw.numbered());
    EXPECT_FALSE(parseOk("a.png").streamed());
}
