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

// GLSL ES's source character set (GLSL ES 3.00 section 3.1) without '#' and '\\', which get
// their own messages: letters, digits, '_', spaces and tabs, and these.
bool inGlslCharacterSet(char c) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x80 || (u < 0x20 && c != '\t') || u == 0x7f) return false;
    return identifierPart(c) || c == ' ' || c == '\t' ||
           std::string_view(".+-/*%<>[](){}^|&~=!:;,?").find(c) != std::string_view::npos;
}

// Why a value cannot follow `#define NAME ` on one line of every pass, or "": the compiler's own
// message would point into toyhost's header, not at --define (issue 46).
std::string valueProblem(const std::string& value) {
    if (value.find_first_of("\r\n") != std::string::npos) return "the value must be one line";
    if (!value.empty() && value.back() == '\\')
        return "the value ends with '\\', which would continue the #define onto the line after it";
    if (value.find('#') != std::string::npos)
        return "the value holds '#': a directive cannot be a macro's value, and GLSL has no # or ## operator";
    // A comment opened and not closed would swallow the line after the #define.
    for (std::size_t at = 0; at + 1 < value.size(); ++at) {
        if (value.compare(at, 2, "//") == 0) break;  // the rest of the line is a comment
        if (value.compare(at, 2, "/*") == 0) {
            const std::size_t end = value.find("*/", at + 2);
            if (end == std::string::npos) return "the value opens a comment ('/*') that it does not close";
            at = end + 1;
        }
    }
    for (std::size_t at = 0; at < value.size(); ++at) {
        if (inGlslCharacterSet(value[at]) || value[at] == '\\') continue;
        std::size_t end = at + 1;  // the whole UTF-8 character
        while (end < value.size() && (static_cast<unsigned char>(value[end]) & 0xC0) == 0x80) ++end;
        const unsigned char u = static_cast<unsigned char>(value[at]);
        std::string shown;
        if (u < 0x20 || u == 0x7f) {
            const char hex[] = "0123456789abcdef";
            shown = std::string("\\x") + hex[u >> 4] + hex[u & 15];
        } else {
            shown = value.substr(at, end - at);
        }
        return "the value holds '" + shown + "', which is not in GLSL's character set (ASCII letters, digits, "
               "spaces and . + - / * % < > [ ] ( ) { } ^ | & ~ = ! : ; , ?)";
    }
    if (value.find('\\') != std::string::npos)
        return "the value holds '\\', which GLSL allows only to continue a line";
    return "";
}

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
    if (define.name == "defined")
        return defineError(shown + ": 'defined' is the preprocessor's operator and cannot be a macro name");
    if (std::string problem = valueProblem(define.value); !problem.empty())
        return defineError("'" + define.name + "': " + problem);
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
