// SourceExcerpt: a user's GLSL file seen the way compiler messages need it: its lines, which bytes
// are comments, where a position the compiler reports really is (Mesa counts columns after its
// preprocessor turned every run of whitespace and comments into one space), the token there, and
// the excerpt printed under a message (the line with a caret under the column). Pure text work;
// no GL needed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/TextExcerpt.h"

namespace toyhost {

struct SourcePosition {
    int line = 0;    // 1-based
    int column = 0;  // 1-based byte column within the line
};

class SourceView {
public:
    explicit SourceView(std::string_view text);

    int lineCount() const { return static_cast<int>(lines_.size()); }
    // Line `n` (1-based) without its newline; "" outside the text.
    std::string_view line(int n) const;
    // True when the byte at (line, column) is part of a comment (or outside the line).
    bool inComment(int line, int column) const;
    // The first / last column of code on `line` (not whitespace, not comment); 0 when the line
    // holds no code.
    int firstCodeColumn(int line) const;
    int lastCodeColumn(int line) const;
    // The nearest line before `line` that holds code, preprocessor directives aside and skipping
    // the branches above an #else or #elif (they exclude the one `line` is in); 0 when none.
    int previousCodeLine(int line) const;
    // "#define", "#else", ... when `line` is a preprocessor directive; "" otherwise.
    std::string directiveOf(int line) const;
    // True when the code has a #line directive of its own: the compiler's line numbers are then
    // the user's chosen ones, not lines of this text.
    bool hasLineDirective() const { return hasLineDirective_; }

    // Where a position in a Mesa message is in this text. Mesa's preprocessor (glcpp) hands the
    // compiler each line with every run of spaces, tabs and comments as one space, so its column
    // counts that text: "    c = x +;" is reported at column 8 for the ';' at column 11. A block
    // comment that spans lines joins them: tokens after it are reported on the line it began on.
    // Columns past the line's end give the position just after its last character. Macros that
    // expand to text of another length shift later columns; callers that know the token they look
    // for correct that with nearestWord().
    SourcePosition fromCompilerPosition(int line, int column) const;

    // The whole-word occurrence of `word` (outside comments) on `line` nearest to `column` (ties go
    // to the later one); 0 when there is none.
    int nearestWord(int line, std::string_view word, int column) const;
    // The token that starts at (line, column): an identifier, a number, or an operator of one or
    // two characters; "" at whitespace, a comment or the end of the line.
    std::string tokenAt(int line, int column) const;
    // Every distinct identifier outside comments, in order of first appearance.
    std::vector<std::string> identifiers() const;
    // The lines of the definitions of function `name` (a type, the name, then '('), outside comments.
    std::vector<int> functionDefinitionLines(std::string_view name) const;
    // The '{' most likely left unclosed, as a line number: the innermost block whose closing '}' is
    // indented differently from the line that opened it, else the outermost '{' never closed;
    // 0 when every '{' is closed.
    int unclosedBraceLine() const;

private:
    std::string_view text_;
    std::vector<std::size_t> lines_;  // offset where each line starts
    std::vector<bool> comment_;       // per byte of text_
    bool hasLineDirective_ = false;

    std::size_t lineEnd(int n) const;
};

}  // namespace toyhost
