// Diagnostics as data: one line per problem in one form, every line with the same prefix, the
// number of lines capped; and the frame counters that pick ping-pong slots.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string_view>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "graph/FrameSequence.h"
#include "graph/PassGraph.h"

using namespace toyhost;

TEST(Diagnostic, FormatPutsEveryKnownPartInItsPlace) {
    Diagnostic d;
    d.message = "undeclared identifier";
    EXPECT_EQ(formatDiagnostic(d), "error: undeclared identifier");
    d.code = Code::ShaderCompile;
    d.file = "/toy/image.glsl";
    d.line = 12;
    d.column = 5;
    d.pass = "Image";
    EXPECT_EQ(formatDiagnostic(d), "/toy/image.glsl:12:5: error: Image: undeclared identifier [shader.compile]");
    d.column = 0;
    d.channel = 2;
    d.severity = Severity::Warning;
    EXPECT_EQ(formatDiagnostic(d), "/toy/image.glsl:12: warning: Image / iChannel2: undeclared identifier [shader.compile]");
    d.line = 0;
    d.field = "passes.\"Image\".channels.iChannel2";  // already names the pass: not repeated
    d.severity = Severity::Notice;
    EXPECT_EQ(formatDiagnostic(d),
              "/toy/image.glsl: notice: passes.\"Image\".channels.iChannel2: undeclared identifier [shader.compile]");
}

TEST(Diagnostic, EveryLineOfAReportHasThePrefixAndTheListIsCapped) {
    std::vector<Diagnostic> many;
    for (int i = 1; i <= 5; ++i) many.push_back(Diagnostic{Severity::Error, Code::Internal, "problem " + std::to_string(i)});
    EXPECT_EQ(formatDiagnostics(many, "toyhost: ", 3),
              "toyhost: error: problem 1 [internal]\ntoyhost: error: problem 2 [internal]\ntoyhost: error: problem 3 [internal]\n"
              "toyhost: ... and 2 more");
    EXPECT_EQ(formatDiagnostics(many, "> ", 5).find("more"), std::string::npos);
    EXPECT_EQ(formatDiagnostics({}, "toyhost: "), "");
}

// A source excerpt is data on the diagnostic; the one-line form stays one line (window titles,
// scripts), the report prints the excerpt under its line without the prefix (the caret keeps its
// column) and the cap still counts diagnostics.
TEST(Diagnostic, AnExcerptFollowsItsLineInReportsOnly) {
    Diagnostic d;
    d.code = Code::ShaderCompile;
    d.file = "/toy/image.glsl";
    d.pass = "Image";
    d.line = 4;
    d.column = 9;
    d.message = "`zz' undeclared";
    d.excerpt = "    4 |     c = zz;\n      |         ^~\n";
    EXPECT_EQ(formatDiagnostic(d), "/toy/image.glsl:4:9: error: Image: `zz' undeclared [shader.compile]");
    EXPECT_EQ(formatDiagnosticWithExcerpt(d, "toyhost: "),
              "toyhost: /toy/image.glsl:4:9: error: Image: `zz' undeclared [shader.compile]\n"
              "    4 |     c = zz;\n      |         ^~");
    const std::vector<Diagnostic> two{d, d};
    EXPECT_EQ(formatDiagnostics(two, "toyhost: ", 1),
              "toyhost: /toy/image.glsl:4:9: error: Image: `zz' undeclared [shader.compile]\n"
              "    4 |     c = zz;\n      |         ^~\ntoyhost: ... and 1 more");
    EXPECT_EQ(Error(two).text(), formatDiagnostics(two));
}

TEST(FrameSequence, RestartResetsIFrameButNeverTheStep) {
    FrameSequence sequence;
    EXPECT_TRUE(sequence.startOfRun());
    for (int i = 0; i < 5; ++i) sequence.advance();
    EXPECT_EQ(sequence.frame(), 5);
    EXPECT_EQ(sequence.step(), 5u);
    sequence.restart();
    EXPECT_EQ(sequence.frame(), 0);
    EXPECT_TRUE(sequence.startOfRun());
    EXPECT_EQ(sequence.step(), 5u);
    sequence.advance();
    EXPECT_EQ(sequence.frame(), 1);
    EXPECT_EQ(sequence.step(), 6u);
}

TEST(FrameSequence, ThePreviousSlotAfterARestartIsTheLastFrameWritten) {
    // A buffer written at step s goes to slotWritten(s); the next frame (step s+1) must read it,
    // whatever iFrame says. Reading by iFrame after a restart at an odd step would pick the
    // other, stale slot.
    FrameSequence sequence;
    for (int i = 0; i < 3; ++i) sequence.advance();
    const std::uint64_t written = sequence.step();  // step 3, then step 4 (the last one) ...
    sequence.advance();
    sequence.advance();
    sequence.restart();  // ... and iFrame 0 is step 5
    EXPECT_EQ(slotRead(FrameAge::Previous, sequence.step()), slotWritten(written + 1));
    EXPECT_NE(slotRead(FrameAge::Previous, sequence.step()), slotWritten(sequence.step()));
    // Counting by iFrame instead would read the slot written at `written`, two frames old.
    EXPECT_EQ(slotRead(FrameAge::Previous, static_cast<std::uint64_t>(sequence.frame())), slotWritten(written));
}

TEST(FrameSequence, ARepeatedFrameHasTheSameIFrameAndReadsItsOwnOutput) {
    FrameSequence sequence;
    sequence.repeat();
    EXPECT_EQ(sequence.frame(), 0) << "nothing rendered yet: nothing to repeat";
    EXPECT_EQ(sequence.step(), 0u);
    for (int i = 0; i < 4; ++i) sequence.advance();  // frames 0..3 rendered, frame 3 shown
    const std::uint64_t shown = sequence.step() - 1;
    sequence.repeat();
    EXPECT_EQ(sequence.frame(), 3) << "the shown frame's iFrame again";
    EXPECT_EQ(sequence.step(), 4u) << "the step goes on";
    // The repeat reads what the shown frame wrote (one more step of each buffer), not what the
    // frame before it wrote.
    EXPECT_EQ(slotRead(FrameAge::Previous, sequence.step()), slotWritten(shown));
    sequence.advance();
    EXPECT_EQ(sequence.frame(), 4) << "the next frame comes after the shown one";
    EXPECT_EQ(sequence.step(), 5u);
    sequence.restart();
    sequence.repeat();
    EXPECT_EQ(sequence.frame(), 0) << "nothing rendered since the restart";
}

TEST(DiagnosticCode, EveryCodeHasItsOwnTextAndTheCategoryDecidesTheKind) {
    std::set<std::string_view> texts;
    int count = 0;
#define TOYHOST_CHECK_CODE(name, number, text, category)                           \
    ++count;                                                                        \
    EXPECT_EQ(codeName(Code::name), std::string_view(text));                        \
    EXPECT_TRUE(texts.insert(codeName(Code::name)).second) << text << " is used twice"; \
    EXPECT_EQ(categoryOf(Code::name), Category::category) << text;
    TOYHOST_DIAGNOSTIC_CODES(TOYHOST_CHECK_CODE)
#undef TOYHOST_CHECK_CODE
    EXPECT_GT(count, 100);
    // Exit codes follow categories: every usage code is a usage error, whatever its text says.
    EXPECT_EQ(Error("bad option", Code::UsageSize).category(), Category::Usage);
    EXPECT_EQ(Error("stopped", Code::Interrupted).category(), Category::Interrupted);
    EXPECT_EQ(categoryName(Category::Shader), "shader");
}

// The numbers compiled into programs that use the library: written out here, not generated from
// the list, so that renumbering a code, reusing a number or adding a code without pinning its new
// number fails. A new code gets the next free number and a row here; a row is never changed.
TEST(DiagnosticCode, EveryNumberIsPinnedAndNeverChanges) {
    const std::map<std::string_view, int> pinned = {
        {"AudioDecode", 0}, {"AudioFfmpegMissing", 1}, {"AudioLive", 2}, {"AudioSettings", 3}, {"AudioTooLong", 4},
        {"BufferNonFinite", 5}, {"Cancelled", 6}, {"CaptureDropped", 7}, {"CaptureException", 8}, {"CaptureFfmpeg", 9},
        {"CaptureFormat", 10}, {"CaptureReadback", 11}, {"CaptureSize", 12}, {"CaptureStopped", 13}, {"CaptureWav", 14},
        {"ChannelUnbound", 15}, {"CheckpointFormat", 16}, {"CheckpointMismatch", 17}, {"CubemapFaceSize", 18},
        {"CubemapLayout", 19}, {"Unclassified", 20}, {"ExportDuplicate", 21}, {"ExportJson", 22}, {"ExportMissing", 23},
        {"ExportMissingBuffer", 24}, {"ExportShape", 25}, {"ExportType", 26}, {"ExportUnsupportedInput", 27},
        {"ExportValue", 28}, {"GlEgl", 29}, {"GlFeature", 30}, {"GlReadback", 31}, {"GlSetup", 32}, {"GlSound", 33},
        {"GlTexture", 34}, {"GlTextureSize", 35}, {"ImageDecode", 36}, {"ImagePngLevel", 37}, {"ImageSize", 38},
        {"ImageTooLarge", 39}, {"InspectRegion", 40}, {"Internal", 41}, {"Interrupted", 42}, {"IoBrokenPipe", 43},
        {"IoExists", 44}, {"IoLinkLoop", 45}, {"IoNoSpace", 46}, {"IoNotAFile", 47}, {"IoNotAFolder", 48},
        {"IoNotFound", 49}, {"IoRead", 50}, {"IoTooLarge", 51}, {"IoWrite", 52}, {"JsonDuplicateKey", 53},
        {"ManifestField", 54}, {"ManifestJson", 55}, {"ManifestMediaNearMiss", 56}, {"ManifestMissing", 57},
        {"ManifestReference", 58}, {"ManifestType", 59}, {"ManifestUnknownField", 60}, {"ManifestUnknownPass", 61},
        {"ManifestUnused", 62}, {"ManifestValue", 63}, {"MediaNotFound", 64}, {"MediaSizeMismatch", 65},
        {"MediaSupplied", 66}, {"MediaStandIn", 67}, {"MediaUnknownStandIn", 68}, {"Process", 69}, {"ScriptEvent", 70},
        {"ScriptJson", 71}, {"ScriptKey", 72}, {"ShaderCompile", 73}, {"ShaderLink", 74}, {"ShaderNonAscii", 75},
        {"ShaderNul", 76}, {"ShaderPreprocess", 77}, {"ShaderPreprocessed", 78}, {"SoundChannel", 79},
        {"SoundEncode", 80}, {"SoundFfmpegMissing", 81}, {"SoundMissing", 82}, {"SoundSkipped", 83},
        {"StateBuffers", 84}, {"StateSize", 85}, {"Usage", 86}, {"UsageDate", 87}, {"UsageOut", 88},
        {"UsagePasses", 89}, {"UsageResume", 90}, {"UsageSize", 91}, {"VideoDecode", 92}, {"VideoDevice", 93},
        {"VideoNoFfmpeg", 94}, {"VideoNoFrames", 95}, {"VideoNoStream", 96}, {"VideoProbe", 97}, {"VideoRate", 98},
        {"VideoRead", 99}, {"VideoSize", 100}, {"VideoStillImage", 101}, {"VolumeDecode", 102},
        {"WatchdogCompile", 103}, {"WatchdogFrame", 104}, {"WatchdogInput", 105}, {"WatchdogOutput", 106},
        {"WatchChanged", 107}, {"WindowCreate", 108}, {"WindowHelp", 109}, {"WindowInit", 110}, {"WindowReload", 111},
        {"WindowScreenshot", 112}, {"ManifestLoneShader", 113},
        {"WindowInspector", 114}, {"ChannelFilter", 115}, {"ShaderLoopCap", 116}, {"ShaderRuleSkipped", 117},
    };
    std::set<int> numbers;
    std::size_t listed = 0;
#define TOYHOST_PIN_CODE(name, number, text, category)                                                        \
    ++listed;                                                                                                 \
    EXPECT_EQ(static_cast<int>(Code::name), number) << #name;                                                 \
    EXPECT_TRUE(numbers.insert(static_cast<int>(Code::name)).second) << #name << "'s number is used twice";   \
    if (auto row = pinned.find(#name); row == pinned.end())                                                   \
        ADD_FAILURE() << #name << " has no pinned number: add its row";                                       \
    else                                                                                                      \
        EXPECT_EQ(static_cast<int>(Code::name), row->second) << #name << " changed its number";
    TOYHOST_DIAGNOSTIC_CODES(TOYHOST_PIN_CODE)
#undef TOYHOST_PIN_CODE
    // A pinned code that is gone: its number stays retired, its row moves to a comment.
    EXPECT_EQ(listed, pinned.size()) << "a pinned code is no longer listed";

    const std::pair<Category, int> categories[] = {
        {Category::Usage, 0}, {Category::Input, 1}, {Category::Shader, 2}, {Category::Output, 3}, {Category::Gl, 4},
        {Category::Interrupted, 5}, {Category::Watchdog, 6}, {Category::Internal, 7}, {Category::Report, 8},
    };
    for (const auto& [category, number] : categories)
        EXPECT_EQ(static_cast<int>(category), number) << categoryName(category);
}
