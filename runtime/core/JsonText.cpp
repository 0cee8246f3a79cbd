#include "core/JsonText.h"

#include <set>
#include <string>
#include <vector>

#include "core/Defaults.h"

namespace toyhost {

using nlohmann::json;

namespace {
// Where the parser is: one entry per open object or array.
struct Level {
    bool array = false;
    long index = -1;              // arrays: the element being read
    std::string key;              // objects: the key being read
    std::set<std::string> keys;   // objects: the keys seen so far
};

std::string pathOf(const std::vector<Level>& levels, std::size_t upTo) {
    std::string path;
    // Appended piece by piece: `"[" + std::to_string(...)` inserts at 0, where GCC 12 warns a false
    // -Wrestrict (GCC bug 105651).
    for (std::size_t i = 0; i < upTo; ++i) {
        if (levels[i].array) {
            path += '[';
            path += std::to_string(levels[i].index);
            path += ']';
        } else {
            if (!path.empty()) path += '.';
            path += levels[i].key;
        }
    }
    return path;
}
}  // namespace

Result<json> parseJsonStrictly(std::string_view text, const std::string& file, Code code) {
    std::vector<Level> levels;
    std::vector<Diagnostic> duplicates;
    std::size_t unlisted = 0;  // duplicates past the first kMaxListedDuplicateKeys: counted, said once
    auto elementStarts = [&] {
        if (!levels.empty() && levels.back().array) ++levels.back().index;
    };
    const json::parser_callback_t track = [&](int, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
                elementStarts();
                levels.push_back(Level{});
                break;
            case json::parse_event_t::array_start:
                elementStarts();
                levels.push_back(Level{true, -1, {}, {}});
                break;
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                if (!levels.empty()) levels.pop_back();
                break;
            case json::parse_event_t::key: {
                Level& level = levels.back();
                level.key = parsed.get<std::string>();
                if (level.keys.insert(level.key).second) break;
                if (duplicates.size() == defaults::kMaxListedDuplicateKeys) {
                    ++unlisted;
                } else {
                    Diagnostic d;
                    d.code = Code::JsonDuplicateKey;
                    d.file = file;
                    d.field = pathOf(levels, levels.size());
                    d.message = "this key appears more than once in its object (JSON keeps only one; remove the other)";
                    duplicates.push_back(std::move(d));
                }
                break;
            }
            case json::parse_event_t::value: elementStarts(); break;
        }
        return true;
    };
    json document;
    try {
        document = json::parse(text, track);
    } catch (const json::exception& e) {
        // parse_error (syntax; its message has the line and column), out_of_range (a number
        // beyond double: 1e400, whose place is where the parser had got to), ...
        Diagnostic d;
        d.code = code;
        d.file = file;
        if (e.id == 406 && !levels.empty()) d.field = pathOf(levels, levels.size());
        d.message = std::string("invalid JSON: ") + e.what();
        return Error(std::move(d));
    }
    if (unlisted > 0) {
        Diagnostic d;
        d.code = Code::JsonDuplicateKey;
        d.file = file;
        d.message = "... and " + std::to_string(unlisted) + " more keys that appear more than once, not listed";
        duplicates.push_back(std::move(d));
    }
    if (!duplicates.empty()) return Error(std::move(duplicates));
    return document;
}

std::string describeJsonValue(const nlohmann::json& value) {
    switch (value.type()) {
        case json::value_t::string: {
            const std::string& text = value.get_ref<const std::string&>();
            if (text.empty()) return "an empty string";
            // Long or multi-line strings are named by their start only: the message is one line.
            std::string shown;
            for (char c : text) {
                if (shown.size() >= 40) {
                    shown += "...";
                    break;
                }
                shown += (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
            }
            return "the string \"" + shown + "\"";
        }
        case json::value_t::number_integer:
        case json::value_t::number_unsigned:
        case json::value_t::number_float: return "the number " + value.dump();
        case json::value_t::boolean: return value.get<bool>() ? "true" : "false";
        case json::value_t::null: return "null";
        case json::value_t::array:
            if (value.empty()) return "an empty array";
            return value.size() == 1 ? "an array of 1 value" : "an array of " + std::to_string(value.size()) + " values";
        case json::value_t::object: return value.empty() ? "an empty object" : "an object";
        default: return value.type_name();
    }
}

}  // namespace toyhost
