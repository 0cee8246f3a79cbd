#include "shader/SourceText.h"

#include <cstdio>

#include "core/Defaults.h"

namespace toyhost {

namespace {
// The UTF-8 sequence at `i` as a code point (or -1 when it is not valid UTF-8) and its length.
std::pair<long, std::size_t> decode(const std::string& s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(i);
    std::size_t length = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 1;
    if (length == 1 || i + length > s.size()) return {-1, 1};
    long cp = b & (0x3F >> (length - 1));
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return {-1, 1};
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    return {cp, length};
}
}  // namespace

void checkShaderText(std::string& code, const std::string& file, const std::string& pass,
                     std::vector<Diagnostic>& problems) {
    if (code.rfind("\xEF\xBB\xBF", 0) == 0) code.erase(0, 3);
    // A binary file would give one error per byte: past the cap they are counted, and said once.
    std::size_t listed = 0, unlisted = 0;
    int lastLine = 1;
    auto problem = [&](int line, int column, std::string message, Code kind) {
        if (listed == defaults::kMaxShaderTextProblems) {
            ++unlisted;
            lastLine = line;
            return;
        }
        ++listed;
        Diagnostic d;
        d.code = kind;
        d.file = file;
        d.pass = pass;
        d.line = line;
        d.column = column;
        d.message = std::move(message);
        problems.push_back(std::move(d));
    };
    enum class State { Code, LineComment, BlockComment } state = State::Code;
    int line = 1, column = 1;
    for (std::size_t i = 0; i < code.size();) {
        const char c = code[i];
        std::size_t advance = 1;
        if (c == '\0') {
            problem(line, column, "a NUL byte: GL would silently ignore everything after it; remove it", Code::ShaderNul);
        } else if (static_cast<unsigned char>(c) >= 0x80) {
            const auto [cp, length] = decode(code, i);
            advance = length;
            if (state == State::Code) {
                char text[96];
                if (cp < 0)
                    std::snprintf(text, sizeof text, "byte 0x%02X (not UTF-8)", static_cast<unsigned char>(c));
                else
                    std::snprintf(text, sizeof text, "character '%s' (U+%04lX)", code.substr(i, length).c_str(), cp);
                problem(line, column,
                        std::string("a non-ASCII ") + text +
                            " outside a comment: GLSL ES allows only ASCII in code (comments may hold any text)",
                        Code::ShaderNonAscii);
            }
        } else if (state == State::Code && c == '/' && i + 1 < code.size() && code[i + 1] == '/') {
            state = State::LineComment;
            advance = 2;
        } else if (state == State::Code && c == '/' && i + 1 < code.size() && code[i + 1] == '*') {
            state = State::BlockComment;
            advance = 2;
        } else if (state == State::BlockComment && c == '*' && i + 1 < code.size() && code[i + 1] == '/') {
            state = State::Code;
            advance = 2;
        } else if (c == '\n') {
            if (state == State::LineComment) state = State::Code;
            ++line;
            column = 0;
        }
        i += advance;
        column += 1;
    }
    if (unlisted > 0) {
        Diagnostic d;
        d.code = Code::ShaderNonAscii;
        d.file = file;
        d.pass = pass;
        d.message = "... and " + std::to_string(unlisted) + " more NUL or non-ASCII bytes up to line " +
                    std::to_string(lastLine) + ", not listed (only the first " +
                    std::to_string(defaults::kMaxShaderTextProblems) + " are): is this file GLSL source text?";
        problems.push_back(std::move(d));
    }
}

}  // namespace toyhost
