#include "shader/MacroDefines.h"

#include <algorithm>
#include <cctype>

namespace toyhost {

namespace {

Error defineError(std::string message) {
    Error error(std::move(message), Code::Usage);
    error.diagnostics.front().field = "defines";
    return error;
}

bool identifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifierPart(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

Result<MacroDefine> parseMacroDefine(std::string_view text) {
    const std::size_t equals = text.find('=');
    MacroDefine define;
    define.name = std::string(text.substr(0, equals));
    define.value = equals == std::string_view::npos ? "1" : std::string(text.substr(equals + 1));
    // Appended piece by piece: `"'" + std::string(...)` inserts at 0, where GCC 12 warns a false
    // -Wrestrict (GCC bug 105651).
    std::string shown = "'";
    shown += text;
    shown += '\'';
    if (define.name.empty())
        return defineError(shown + " has no name: expected NAME or NAME=VALUE");
    if (!identifierStart(define.name.front()) || !std::all_of(define.name.begin(), define.name.end(), identifierPart))
        return defineError(shown + ": '" + define.name +
                           "' is not a macro name (letters, digits and '_', not starting with a digit)");
    if (define.name.starts_with("GL_") || define.name.find("__") != std::string::npos)
        return defineError(shown + ": GLSL ES reserves names starting with GL_ or containing __");
    if (define.value.find_first_of("\r\n") != std::string::npos)
        return defineError("'" + define.name + "': the value must be one line");
    return define;
}

Result<MacroDefines> parseMacroDefines(std::span<const std::string> texts) {
    MacroDefines defines;
    for (const std::string& text : texts) {
        Result<MacroDefine> define = parseMacroDefine(text);
        if (!define) return define.error();
        auto same = std::find_if(defines.begin(), defines.end(),
                                 [&](const MacroDefine& d) { return d.name == define->name; });
        if (same == defines.end()) defines.push_back(std::move(*define));
        else if (same->value != define->value)
            return defineError("'" + define->name + "' is given twice with different values ('" + same->value +
                               "' and '" + define->value + "')");
    }
    return defines;
}

std::string macroDefineLines(std::span<const MacroDefine> defines) {
    std::string lines;
    for (const MacroDefine& define : defines) lines += "#define " + define.name + " " + define.value + "\n";
    return lines;
}

}  // namespace toyhost
