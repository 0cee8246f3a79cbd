// JsonText: parsing the JSON a user wrote (manifests, exports, input scripts) strictly: a syntax
// error or a number out of range (1e400) is an error, never an exception that escapes, and a key
// that appears twice in one object is an error naming its path, where a plain parser would keep
// the last one silently. No GL needed.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>

#include "core/Result.h"

namespace toyhost {

// `file` names the text in errors; `code` is the diagnostic code of a syntax error ("manifest.json",
// Code::ExportJson, ...). Duplicate keys are reported with code Code::JsonDuplicateKey, all at once.
Result<nlohmann::json> parseJsonStrictly(std::string_view text, const std::string& file, Code code);

// Whether `text` is valid UTF-8, which every JSON string must be (nlohmann's dump throws on
// anything else): a value headed for a JSON file is checked with this first.
bool isValidUtf8(std::string_view text);

// `value` when it is a JSON integer (no fraction, no exponent: 8.9 and 8.0 are not) from `min` to
// `max`; nullopt otherwise, where nlohmann's get<int>() would truncate 8.9 to 8 and wrap
// 4294967304 to 8. Messages describe the value with describeJsonValue.
std::optional<long long> jsonWholeNumber(const nlohmann::json& value, long long min, long long max);

// What a JSON value is, in words for a message that says what was expected instead: "an empty
// string", "the string \"abc\"", "the number 5", "true", "null", "an empty array", "an array of
// 2 values", "an object". (nlohmann's type_name() says "string" for "" too, which reads as a
// contradiction after "must be a non-empty string, not ...".)
std::string describeJsonValue(const nlohmann::json& value);

// A syntax error of nlohmann's parser (its what()) in words for a person who wrote the JSON by
// hand, without the parser's own terms: "found '/': JSON has no comments ...", "expected a key in
// double quotes, found ...". parseJsonStrictly puts the line and column in the Diagnostic.
std::string jsonSyntaxMessage(std::string_view what);

}  // namespace toyhost
