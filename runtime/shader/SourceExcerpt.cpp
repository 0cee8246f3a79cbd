#include "shader/SourceExcerpt.h"

#include <algorithm>
#include <cstdlib>
#include <set>

namespace toyhost {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool isIdentifierStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentifierChar(char c) { return isIdentifierStart(c) || isDigit(c); }

// Words before a '(' that are not a return type: `return f(x)` is a call, not a definition.
bool isStatementKeyword(std::string_view word) {
    static const std::set<std::string_view> keywords{"return", "else", "case", "do", "if", "while", "for", "switch"};
    return keywords.count(word) > 0;
}

// How far a line is indented, a tab counting as four spaces.
int indentOf(std::string_view line) {
    int width = 0;
    for (char c : line) {
        if (c == ' ') ++width;
        else if (c == '\t') width += 4;
        else break;
    }
    return width;
}

}  // namespace

SourceView::SourceView(std::string_view text) : text_(text), comment_(text.size(), false) {
    lines_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') lines_.push_back(i + 1);
    if (!text.empty() && text.back() == '\n') lines_.pop_back();  // no empty line after the last newline

    // Comments (GLSL has no string literals, so nothing else can hide a comment marker).
    for (std::size_t i = 0; i < text.size();) {
        if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n') comment_[i++] = true;
        } else if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const std::size_t end = text.find("*/", i + 2);
            const std::size_t stop = end == std::string_view::npos ? text.size() : end + 2;
            while (i < stop) comment_[i++] = true;
        } else {
            ++i;
        }
    }
    for (int n = 1; n <= lineCount(); ++n)
        if (directiveOf(n) == "#line") hasLineDirective_ = true;
}

std::size_t SourceView::lineEnd(int n) const {
    if (n < lineCount()) return lines_[n] - 1;
    return !text_.empty() && text_.back() == '\n' ? text_.size() - 1 : text_.size();
}

std::string_view SourceView::line(int n) const {
    if (n < 1 || n > lineCount()) return {};
    std::string_view text = text_.substr(lines_[n - 1], lineEnd(n) - lines_[n - 1]);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    return text;
}

bool SourceView::inComment(int n, int column) const {
    if (n < 1 || n > lineCount() || column < 1) return true;
    const std::size_t at = lines_[n - 1] + static_cast<std::size_t>(column - 1);
    return at >= lineEnd(n) || comment_[at];
}

int SourceView::firstCodeColumn(int n) const {
    const std::string_view text = line(n);
    for (int c = 1; c <= static_cast<int>(text.size()); ++c)
        if (!isSpace(text[c - 1]) && !inComment(n, c)) return c;
    return 0;
}

int SourceView::lastCodeColumn(int n) const {
    const std::string_view text = line(n);
    for (int c = static_cast<int>(text.size()); c >= 1; --c)
        if (!isSpace(text[c - 1]) && !inComment(n, c)) return c;
    return 0;
}

std::string SourceView::directiveOf(int n) const {
    const int first = firstCodeColumn(n);
    if (first == 0 || line(n)[first - 1] != '#') return "";
    std::string_view rest = line(n).substr(first);
    while (!rest.empty() && isSpace(rest.front())) rest.remove_prefix(1);
    std::size_t end = 0;
    while (end < rest.size() && isIdentifierChar(rest[end])) ++end;
    std::string directive = "#";  // appended, not insert(0, "#"): GCC 12 warns a false -Wrestrict there
    directive += rest.substr(0, end);
    return directive;
}

int SourceView::previousCodeLine(int n) const {
    for (int p = std::min(n, lineCount() + 1) - 1; p >= 1; --p) {
        const std::string directive = directiveOf(p);
        if (directive.empty()) {
            if (firstCodeColumn(p) != 0) return p;
            continue;
        }
        // Above an #else or #elif is the branch that was not taken when this one was: go on above
        // the #if that opened them.
        if (directive == "#else" || directive == "#elif") {
            for (int depth = 0; p > 1; --p) {
                const std::string above = directiveOf(p - 1);
                if (above == "#endif") ++depth;
                else if (above.rfind("#if", 0) == 0 && depth-- == 0) {
                    --p;
                    break;
                }
            }
        }
    }
    return 0;
}

SourcePosition SourceView::fromCompilerPosition(int n, int column) const {
    if (n < 1 || n > lineCount() || column < 1) return {n, column};
    auto positionOf = [&](std::size_t offset) {
        const auto after = std::upper_bound(lines_.begin(), lines_.end(), offset);
        const int found = static_cast<int>(after - lines_.begin());
        return SourcePosition{found, static_cast<int>(offset - lines_[found - 1]) + 1};
    };
    int collapsed = 0;
    bool inSpace = false;
    std::size_t at = lines_[n - 1];
    for (; at < text_.size(); ++at) {
        const char c = text_[at];
        if (c == '\n' && !comment_[at]) break;
        if (comment_[at] || isSpace(c) || c == '\n') {
            if (inSpace) continue;
            inSpace = true;
        } else {
            inSpace = false;
        }
        if (++collapsed == column) return positionOf(at);
    }
    // Past the end of the joined line: just after its last character.
    if (at > lines_[n - 1] && at <= text_.size() && at > 0 && text_[at - 1] == '\r') --at;
    return positionOf(at);
}

int SourceView::nearestWord(int n, std::string_view word, int column) const {
    const std::string_view text = line(n);
    int best = 0;
    for (std::size_t at = text.find(word); !word.empty() && at != std::string_view::npos; at = text.find(word, at + 1)) {
        const bool startsWord = at == 0 || !isIdentifierChar(text[at - 1]);
        const bool endsWord = at + word.size() >= text.size() || !isIdentifierChar(text[at + word.size()]);
        const int c = static_cast<int>(at) + 1;
        if (!startsWord || !endsWord || inComment(n, c)) continue;
        if (best == 0 || std::abs(c - column) <= std::abs(best - column)) best = c;
    }
    return best;
}

std::string SourceView::tokenAt(int n, int column) const {
    const std::string_view text = line(n);
    if (column < 1 || column > static_cast<int>(text.size()) || inComment(n, column)) return "";
    const std::size_t start = static_cast<std::size_t>(column - 1);
    const char c = text[start];
    std::size_t end = start + 1;
    if (isIdentifierStart(c)) {
        while (end < text.size() && isIdentifierChar(text[end])) ++end;
    } else if (isDigit(c) || (c == '.' && end < text.size() && isDigit(text[end]))) {
        while (end < text.size() && (isDigit(text[end]) || text[end] == '.')) ++end;
        if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
            std::size_t e = end + 1;
            if (e < text.size() && (text[e] == '+' || text[e] == '-')) ++e;
            if (e < text.size() && isDigit(text[e])) {
                end = e;
                while (end < text.size() && isDigit(text[end])) ++end;
            }
        }
        if (end < text.size() && (text[end] == 'u' || text[end] == 'U' || text[end] == 'f' || text[end] == 'F')) ++end;
    } else if (isSpace(c)) {
        return "";
    } else if (end < text.size()) {
        static const std::set<std::string_view> pairs{"++", "--", "+=", "-=", "*=", "/=", "%=", "==", "!=", "<=", ">=",
                                                      "&&", "||", "^^", "<<", ">>", "&=", "|=", "^="};
        if (pairs.count(text.substr(start, 2))) end = start + 2;
    }
    return std::string(text.substr(start, end - start));
}

std::vector<std::string> SourceView::identifiers() const {
    std::vector<std::string> out;
    std::set<std::string> seen;
    bool afterHash = false;
    for (std::size_t i = 0; i < text_.size();) {
        const char c = text_[i];
        if (comment_[i]) {
            ++i;
        } else if (isIdentifierStart(c)) {
            std::size_t end = i;
            while (end < text_.size() && isIdentifierChar(text_[end])) ++end;
            std::string word(text_.substr(i, end - i));
            if (!afterHash && seen.insert(word).second) out.push_back(std::move(word));
            afterHash = false;
            i = end;
        } else if (isDigit(c)) {
            while (i < text_.size() && (isIdentifierChar(text_[i]) || text_[i] == '.')) ++i;  // 1e3, 2.0f, 0x1F
            afterHash = false;
        } else {
            if (!isSpace(c)) afterHash = c == '#';
            ++i;
        }
    }
    return out;
}

std::vector<int> SourceView::functionDefinitionLines(std::string_view name) const {
    std::vector<int> out;
    for (int n = 1; n <= lineCount() && !name.empty(); ++n) {
        const std::string_view text = line(n);
        for (std::size_t at = text.find(name); at != std::string_view::npos; at = text.find(name, at + 1)) {
            const std::size_t end = at + name.size();
            if ((at > 0 && isIdentifierChar(text[at - 1])) || (end < text.size() && isIdentifierChar(text[end])) ||
                inComment(n, static_cast<int>(at) + 1))
                continue;
            // After the name: '(' (spaces allowed). Before it: a word that is not a keyword.
            std::size_t after = end;
            while (after < text.size() && isSpace(text[after])) ++after;
            std::size_t before = at;
            while (before > 0 && isSpace(text[before - 1])) --before;
            std::size_t wordStart = before;
            while (wordStart > 0 && isIdentifierChar(text[wordStart - 1])) --wordStart;
            const std::string_view type = text.substr(wordStart, before - wordStart);
            if (after < text.size() && text[after] == '(' && !type.empty() && isIdentifierStart(type.front()) &&
                !isStatementKeyword(type)) {
                out.push_back(n);
                break;
            }
        }
    }
    return out;
}

int SourceView::unclosedBraceLine() const {
    struct Open {
        int line;
        int indent;
    };
    std::vector<Open> open;
    int suspect = 0;
    for (int n = 1; n <= lineCount(); ++n) {
        const std::string_view text = line(n);
        for (int c = 1; c <= static_cast<int>(text.size()); ++c) {
            if (inComment(n, c)) continue;
            if (text[c - 1] == '{') {
                open.push_back({n, indentOf(text)});
            } else if (text[c - 1] == '}' && !open.empty()) {
                // A '}' closing a block opened at another indentation probably belongs to an outer
                // block: the first such block is the one whose own '}' was forgotten.
                if (suspect == 0 && open.back().line != n && open.back().indent != indentOf(text)) suspect = open.back().line;
                open.pop_back();
            }
        }
    }
    if (open.empty()) return 0;
    return suspect != 0 ? suspect : open.front().line;
}

}  // namespace toyhost
