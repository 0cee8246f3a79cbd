#include "input/KeyCodes.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <string>
#include <utility>

namespace toyhost {

namespace {

struct NamedKey {
    std::string_view name;  // lower case
    int code;
};

constexpr std::array kNamedKeys = {
    NamedKey{"backspace", 8},     NamedKey{"tab", 9},           NamedKey{"enter", 13},
    NamedKey{"return", 13},       NamedKey{"shift", 16},        NamedKey{"ctrl", 17},
    NamedKey{"control", 17},      NamedKey{"alt", 18},          NamedKey{"pause", 19},
    NamedKey{"capslock", 20},     NamedKey{"escape", 27},       NamedKey{"esc", 27},
    NamedKey{"space", 32},        NamedKey{"pageup", 33},       NamedKey{"pagedown", 34},
    NamedKey{"end", 35},          NamedKey{"home", 36},         NamedKey{"left", 37},
    NamedKey{"up", 38},           NamedKey{"right", 39},        NamedKey{"down", 40},
    NamedKey{"arrowleft", 37},    NamedKey{"arrowup", 38},      NamedKey{"arrowright", 39},
    NamedKey{"arrowdown", 40},    NamedKey{"insert", 45},       NamedKey{"delete", 46},
    NamedKey{"meta", 91},         NamedKey{"semicolon", 186},   NamedKey{"equal", 187},
    NamedKey{"comma", 188},       NamedKey{"minus", 189},       NamedKey{"period", 190},
    NamedKey{"slash", 191},       NamedKey{"backquote", 192},   NamedKey{"bracketleft", 219},
    NamedKey{"backslash", 220},   NamedKey{"bracketright", 221}, NamedKey{"quote", 222},
};

bool allDigits(std::string_view s) {
    return !s.empty() && std::ranges::all_of(s, [](unsigned char c) { return std::isdigit(c); });
}

// "f1".."f12" -> 112..123, "numpad0".."numpad9" -> 96..105, else -1.
int numberedKey(std::string_view lower) {
    auto suffix = [&](std::string_view prefix, int lo, int hi) {
        if (!lower.starts_with(prefix)) return -1;
        std::string_view digits = lower.substr(prefix.size());
        if (!allDigits(digits) || digits.size() > 2 || (digits.size() == 2 && digits[0] == '0'))
            return -1;
        int n = 0;
        std::from_chars(digits.data(), digits.data() + digits.size(), n);
        return (n >= lo && n <= hi) ? n : -1;
    };
    if (int n = suffix("numpad", 0, 9); n >= 0) return 96 + n;
    if (int n = suffix("f", 1, 12); n >= 0) return 111 + n;
    return -1;
}

}  // namespace

Result<int> keyCodeFromName(std::string_view name) {
    std::string lower(name);
    std::ranges::transform(lower, lower.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });

    if (lower.size() == 1) {
        char c = lower[0];
        if (c >= 'a' && c <= 'z') return int{c - 'a' + 'A'};  // keyCode of a letter is its capital
        if (c >= '0' && c <= '9') return int{c};
    }
    if (allDigits(lower)) {
        long long code = -1;
        auto [end, ec] = std::from_chars(lower.data(), lower.data() + lower.size(), code);
        if (ec != std::errc() || code > 255)
            return Error("key code " + lower + " is out of range 0..255", Code::ScriptKey);
        return static_cast<int>(code);
    }
    for (const NamedKey& key : kNamedKeys)
        if (key.name == lower) return key.code;
    if (int code = numberedKey(lower); code >= 0) return code;
    return Error("unknown key \"" + std::string(name) + "\"", Code::ScriptKey);
}

}  // namespace toyhost
