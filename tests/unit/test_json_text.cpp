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
