#include "core/JsonText.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "core/Defaults.h"
#include "core/TextExcerpt.h"

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

std::string afterPrefix(std::string_view text, std::string_view prefix) {
    return std::string(text.starts_with(prefix) ? text.substr(prefix.size()) : text);
}

// nlohmann's "expected ..." in words.
std::string expectedInWords(const std::string& expected, const std::string& context) {
    if (expected == "string literal") return context == "object key" ? "a key in double quotes" : "a string in double quotes";
    if (expected == "'[', '{', or a literal") return "a value (a number, a string in double quotes, true, false, null, [ or {)";
    if (expected == "end of input") return "the end of the text";
    return expected;
}

}  // namespace

std::string jsonSyntaxMessage(std::string_view what) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error while parsing
    // object key - invalid literal; last read: '/'; expected string literal"
    std::string_view rest = what;
    if (std::size_t colon = rest.find(": "); rest.starts_with("[json.exception") && colon != std::string_view::npos)
        rest.remove_prefix(colon + 2);
    std::string text = afterPrefix(rest, "syntax error ");
    std::string context;
    if (text.starts_with("while parsing ")) {
        const std::size_t dash = text.find(" - ");
        context = text.substr(14, dash == std::string::npos ? std::string::npos : dash - 14);
        text = dash == std::string::npos ? "" : text.substr(dash + 3);
    }
    std::string reason = text, lastRead, expected;
    for (std::size_t at; (at = reason.rfind("; ")) != std::string::npos;) {
        const std::string piece = reason.substr(at + 2);
        reason.erase(at);
        if (piece.starts_with("last read: ")) lastRead = piece.substr(11);
        else if (piece.starts_with("expected ")) expected = piece.substr(9);
    }
    // "last read" is the lexer's whole token ('{<U+000A>  /' for a comment after a brace): a word
    // is shown whole ('True'), anything else by its last character (or <U+...> escape), the one
    // that does not fit.
    if (lastRead.size() > 3 && lastRead.front() == '\'' && lastRead.back() == '\'') {
        const std::string inner = lastRead.substr(1, lastRead.size() - 2);
        const bool word = std::all_of(inner.begin(), inner.end(), [](unsigned char c) {
            return std::isalnum(c) || c == '_' || c == '-' || c == '+' || c == '.';
        });
        if (!word) {
            const std::size_t escape = inner.rfind("<U+");
            const bool endsInEscape = inner.back() == '>' && escape != std::string::npos;
            lastRead = "'" + (endsInEscape ? inner.substr(escape) : inner.substr(inner.size() - 1)) + "'";
        }
    }
    if (lastRead.size() == 3 && static_cast<unsigned char>(lastRead[1]) >= 0x80) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(lastRead[1]));
        return std::string("found the byte ") + hex + ", which is not JSON outside a string (a stray byte, or a file in "
               "another encoding than UTF-8?)";
    }
    std::string found = lastRead;
    if (reason.starts_with("unexpected ")) found = reason.substr(11);
    // The usual slips of hand-written JSON first.
    if (found.starts_with("'/"))
        return "found " + found + ": JSON has no comments (remove it, or put the note in a \"note\" field)";
    if (reason == "unexpected '}'" || reason == "unexpected ']'")
        if (context == "object key" || context == "value")
            return "found " + found + " after a comma: JSON allows no comma before a closing bracket";
    if (reason.starts_with("unexpected end of input"))
        return "the text ends too early" + (expected.empty() ? std::string() : ": expected " + expectedInWords(expected, context));
    if (reason == "invalid literal" && !lastRead.empty())
        return "found " + lastRead + ", which is not JSON: strings need double quotes; true, false and null are lowercase" +
               (expected.empty() ? std::string() : "; expected " + expectedInWords(expected, context));
    if (reason.starts_with("invalid string: ")) return reason.substr(16);
    if (!expected.empty()) return "expected " + expectedInWords(expected, context) + (found.empty() ? "" : ", found " + found);
    return reason.empty() ? std::string(rest) : reason;
}

namespace {

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

namespace {

// Where in `text` the number `literal` stands as a whole JSON token (after ':', '[', ',' or space,
// before ',', ']', '}', space or the end), or npos: nlohmann's "number overflow" says which
// number, not where.
std::size_t numberTokenAt(std::string_view text, std::string_view literal) {
    const auto separates = [](char c) { return c == ',' || c == ']' || c == '}' || c == ':' || c == '[' || std::isspace(static_cast<unsigned char>(c)); };
    for (std::size_t at = text.find(literal); at != std::string_view::npos; at = text.find(literal, at + 1)) {
        const std::size_t end = at + literal.size();
        if ((at == 0 || separates(text[at - 1])) && (end == text.size() || separates(text[end]))) return at;
    }
    return std::string_view::npos;
}

Diagnostic placed(Diagnostic d, std::string_view text, std::size_t offset) {
    const TextPlace place = placeOfOffset(text, offset);
    d.line = place.line;
    d.column = place.column;
    d.excerpt = formatExcerpt(place.lineText, place.line, place.column);
    return d;
}

}  // namespace

Result<json> parseJsonStrictly(std::string_view text, const std::string& file, Code code) {
    // nlohmann's lexer takes a NUL byte for the end of the text ("the text ends too early").
    if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos) {
        Diagnostic d;
        d.code = code;
        d.file = file;
        d.message = "invalid JSON: found a NUL byte (0x00), which JSON text cannot hold (a binary file, or text in "
                    "UTF-16?)";
        return Error(placed(std::move(d), text, nul));
    }
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
        const std::string_view what = e.what();
        const std::size_t quote = what.find("number overflow parsing '");
        if (const auto* syntax = dynamic_cast<const json::parse_error*>(&e); syntax && syntax->byte > 0) {
            // byte: 1-based index of the last byte read, the one that does not fit.
            d.message = "invalid JSON: " + jsonSyntaxMessage(e.what());
            d = placed(std::move(d), text, syntax->byte - 1);
        } else if (e.id == 406 && quote != std::string_view::npos && what.back() == '\'') {
            const std::string_view literal = what.substr(quote + 25, what.size() - quote - 26);
            d.message = "invalid JSON: the number " + std::string(literal) +
                        " is beyond the range of numbers (at most about 1.8e308 either way)";
            if (const std::size_t at = numberTokenAt(text, literal); at != std::string_view::npos)
                d = placed(std::move(d), text, at);
        } else {
            d.message = std::string("invalid JSON: ") + e.what();
        }
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

bool isValidUtf8(std::string_view text) {
    // The serializer's own check (type_error 316), so that "valid" means what dump() accepts.
    try {
        (void)json(std::string(text)).dump();
        return true;
    } catch (const json::type_error&) {
        return false;
    }
}

std::optional<long long> jsonWholeNumber(const json& value, long long min, long long max) {
    long long number = 0;
    if (value.is_number_unsigned()) {
        const auto big = value.get<unsigned long long>();
        if (big > static_cast<unsigned long long>(std::numeric_limits<long long>::max())) return std::nullopt;
        number = static_cast<long long>(big);
    } else if (value.is_number_integer()) {
        number = value.get<long long>();
    } else {
        return std::nullopt;
    }
    if (number < min || number > max) return std::nullopt;
    return number;
}

}  // namespace toyhost
