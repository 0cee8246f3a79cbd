// Diagnostics as data: one line per problem in one form, every line with the same prefix, the
// number of lines capped; and the frame counters that pick ping-pong slots.
#include <gtest/gtest.h>

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

TEST(DiagnosticCode, EveryCodeHasItsOwnTextAndTheCategoryDecidesTheKind) {
    std::set<std::string_view> texts;
    int count = 0;
#define TOYHOST_CHECK_CODE(name, text, category)                                   \
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
