// TextExcerpt: the excerpt printed under a message about a place in a user's text (a shader line,
// a manifest's JSON): the line, numbered, and a caret under the column. Pure text; no GL needed.
#pragma once

#include <string>
#include <string_view>

namespace toyhost {

// The excerpt under a message: "  NN | " and the line, then a line with a caret under `column`
// (followed by `width - 1` tildes when the problem spans a token). Tabs before the column are kept
// in the caret line so that the caret stays under its character; a very long line is cut to a
// window around the column. Ends with a newline.
std::string formatExcerpt(std::string_view lineText, int lineNumber, int column, int width = 1);

// The 1-based line and column of byte `offset` of `text`, and that line's text (no newline).
struct TextPlace {
    int line = 1;
    int column = 1;
    std::string_view lineText;
};
TextPlace placeOfOffset(std::string_view text, std::size_t offset);

}  // namespace toyhost
