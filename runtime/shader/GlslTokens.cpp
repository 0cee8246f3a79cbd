#include "shader/GlslTokens.h"

#include <cctype>
#include <map>

namespace toyhost {

int glslBinaryStrength(std::string_view op) {
    static const std::map<std::string_view, int> strengths = {
        {"||", 1}, {"^^", 2}, {"&&", 3}, {"|", 4},  {"^", 5},  {"&", 6},  {"==", 7}, {"!=", 7}, {"<", 8}, {">", 8},
        {"<=", 8}, {">=", 8}, {"<<", 9}, {">>", 9}, {"+", 10}, {"-", 10}, {"*", 11}, {"/", 11}, {"%", 11}};
    const auto found = strengths.find(op);
    return found == strengths.end() ? 0 : found->second;
}

bool isIdentifierStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::vector<GlslToken> tokenizeGlsl(std::string_view s) {
    std::vector<GlslToken> out;
    bool inDirective = false;  // until the end of a line not continued by `\`
    bool lineHasToken = false;
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '\n') {
            const bool continued = i > 0 && (s[i - 1] == '\\' || (s[i - 1] == '\r' && i > 1 && s[i - 2] == '\\'));
            if (!continued) inDirective = false, lineHasToken = false;
            ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(c)) || c == '\\') {
            ++i;
            continue;
        }
        if (s.compare(i, 2, "//") == 0) {
            // A line comment ends at the newline, which still ends a directive.
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (s.compare(i, 2, "/*") == 0) {
            const std::size_t end = s.find("*/", i + 2);
            i = end == std::string_view::npos ? s.size() : end + 2;
            continue;
        }
        GlslToken t;
        t.offset = i;
        if (c == '#' && !lineHasToken) {
            inDirective = true;
            t.directiveStart = true;
        }
        t.directive = inDirective;
        lineHasToken = true;
        std::size_t j = i + 1;
        if (isIdentifierStart(c)) {
            t.kind = GlslToken::Kind::Identifier;
            while (j < s.size() && isIdentifierChar(s[j])) ++j;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            t.kind = GlslToken::Kind::Number;
            while (j < s.size()) {
                const char d = s[j];
                if (isIdentifierChar(d) || d == '.') ++j;
                else if ((d == '+' || d == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E') &&
                         !(s[i] == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X'))) ++j;
                else break;
            }
        } else {
            // Two-character operators matter only where `=` must not be read as an assignment.
            static constexpr std::string_view kPairs[] = {"==", "!=", "<=", ">=", "+=", "-=", "*=", "/=", "%=",
                                                          "&=", "|=", "^=", "++", "--", "&&", "||", "^^", "<<", ">>", "##"};
            for (std::string_view p : kPairs)
                if (s.compare(i, 2, p) == 0) j = i + 2;
        }
        t.text = s.substr(i, j - i);
        out.push_back(t);
        i = j;
    }
    return out;
}

}  // namespace toyhost
