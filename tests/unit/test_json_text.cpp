// parseJsonStrictly: a key twice in one object is an error with its place (JSON keeps one of them
// silently); past the first few they are counted in one line, never dropped without a word.
#include <gtest/gtest.h>

#include "core/Defaults.h"
#include "core/JsonText.h"

using namespace toyhost;

TEST(JsonText, ADuplicateKeyIsNamedWithItsPath) {
    Result<nlohmann::json> parsed = parseJsonStrictly(R"({"passes": {"Image": {"a": 1, "a": 2}}})", "m.json", Code::ManifestJson);
    ASSERT_FALSE(parsed.ok());
    ASSERT_EQ(parsed.error().diagnostics.size(), 1u);
    EXPECT_EQ(parsed.error().first().field, "passes.Image.a");
    EXPECT_EQ(parsed.error().first().code, Code::JsonDuplicateKey);
}

TEST(JsonText, ManyDuplicatesAreListedUpToTheCapAndTheRestCounted) {
    std::string text = "{";
    for (int i = 0; i < 100; ++i) text += "\"k" + std::to_string(i) + "\": 1, \"k" + std::to_string(i) + "\": 2, ";
    text += "\"end\": 0}";
    Result<nlohmann::json> parsed = parseJsonStrictly(text, "m.json", Code::ManifestJson);
    ASSERT_FALSE(parsed.ok());
    const auto& list = parsed.error().diagnostics;
    ASSERT_EQ(list.size(), defaults::kMaxListedDuplicateKeys + 1);
    EXPECT_EQ(list.front().field, "k0");
    EXPECT_NE(list.back().message.find("and " + std::to_string(100 - defaults::kMaxListedDuplicateKeys) + " more keys"),
              std::string::npos)
        << list.back().message;
}

// A syntax error says where (line, column, the line with a caret) and what, in words for a person
// who wrote the JSON by hand, without the parser's own terms.
namespace {
Diagnostic syntaxError(const std::string& text) {
    Result<nlohmann::json> parsed = parseJsonStrictly(text, "manifest.json", Code::ManifestJson);
    EXPECT_FALSE(parsed.ok());
    return parsed.ok() ? Diagnostic{} : parsed.error().first();
}
}  // namespace

TEST(JsonText, ASyntaxErrorHasItsLineColumnAndExcerpt) {
    const Diagnostic d = syntaxError("{\n  \"passes\": {\n    \"Image\": { \"source\": \"image.glsl\" },\n  }\n}\n");
    EXPECT_EQ(d.line, 4);
    EXPECT_EQ(d.column, 3);
    EXPECT_EQ(d.code, Code::ManifestJson);
    EXPECT_EQ(d.message, "invalid JSON: found '}' after a comma: JSON allows no comma before a closing bracket");
    EXPECT_EQ(d.excerpt, "    4 |   }\n      |   ^\n");
    EXPECT_EQ(formatDiagnostic(d).rfind("manifest.json:4:3: error: invalid JSON: ", 0), 0u) << formatDiagnostic(d);
    EXPECT_EQ(d.message.find("json.exception"), std::string::npos);
}

TEST(JsonText, TheUsualSlipsAreNamed) {
    Diagnostic d = syntaxError("{\n  // the ocean\n  \"name\": \"x\"\n}");
    EXPECT_EQ(d.line, 2);
    EXPECT_NE(d.message.find("JSON has no comments"), std::string::npos) << d.message;
    d = syntaxError("{\"name\": 'x'}");
    EXPECT_EQ(d.line, 1);
    EXPECT_EQ(d.column, 10);
    EXPECT_NE(d.message.find("strings need double quotes"), std::string::npos) << d.message;
    d = syntaxError("{name: \"x\"}");
    EXPECT_NE(d.message.find("strings need double quotes"), std::string::npos) << d.message;
    d = syntaxError("{\"passes\": {\"Image\": {}}");
    EXPECT_NE(d.message.find("the text ends too early"), std::string::npos) << d.message;
    d = syntaxError("{\"a\": 1 \"b\": 2}");
    EXPECT_NE(d.message.find("expected"), std::string::npos) << d.message;
    EXPECT_EQ(d.message.find("json.exception"), std::string::npos) << d.message;
    d = syntaxError("");
    EXPECT_EQ(d.line, 1);
    EXPECT_NE(d.message.find("the text ends too early"), std::string::npos) << d.message;
}

TEST(JsonText, AWindowsLineEndingIsNotPartOfTheExcerpt) {
    const Diagnostic d = syntaxError("{\r\n  \"a\": 1,\r\n}\r\n");
    EXPECT_EQ(d.line, 3);
    EXPECT_EQ(d.excerpt, "    3 | }\n      | ^\n");
}

TEST(JsonText, AStrayByteIsNamedByItsValue) {
    const Diagnostic d = syntaxError("{\"a\": 1}\xff");
    EXPECT_EQ(d.column, 9);
    EXPECT_NE(d.message.find("found the byte 0xFF"), std::string::npos) << d.message;
}

// Once unclear (issue 46): a NUL byte read as the end of the text ("the text ends too early"), and
// a number beyond double (1e400) said in the parser's own words, with no line or column.
TEST(JsonText, ANulByteAndANumberBeyondDoubleAreNamedWithTheirPlace) {
    using namespace std::string_literals;
    Diagnostic d = syntaxError("{\n  \"name\": \"x\",\0\n  \"a\": 1\n}"s);
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 15);
    EXPECT_NE(d.message.find("found a NUL byte (0x00)"), std::string::npos) << d.message;
    EXPECT_EQ(d.message.find("ends too early"), std::string::npos) << d.message;
    d = syntaxError("{\n  \"defaults\": {\"fps\": 1e400}\n}");
    EXPECT_EQ(d.line, 2);
    EXPECT_EQ(d.column, 23);
    EXPECT_EQ(d.field, "defaults.fps");
    EXPECT_EQ(d.message, "invalid JSON: the number 1e400 is beyond the range of numbers (at most about 1.8e308 either way)");
    EXPECT_EQ(d.excerpt, "    2 |   \"defaults\": {\"fps\": 1e400}\n      |                       ^\n");
    EXPECT_EQ(d.message.find("json.exception"), std::string::npos) << d.message;
}
