#include "core/TextExcerpt.h"

#include <algorithm>

namespace toyhost {

std::string formatExcerpt(std::string_view lineText, int lineNumber, int column, int width) {
    // A minified shader can have a line of thousands of characters: show 60 on either side.
    constexpr int kSide = 60;
    std::string shown(lineText);
    int caret = std::max(column, 1);
    if (static_cast<int>(lineText.size()) > 2 * kSide + 20) {
        const int from = std::max(0, caret - 1 - kSide);
        const int to = std::min(static_cast<int>(lineText.size()), caret - 1 + kSide);
        shown = (from > 0 ? "..." : "") + std::string(lineText.substr(from, to - from)) +
                (to < static_cast<int>(lineText.size()) ? "..." : "");
        caret = caret - from + (from > 0 ? 3 : 0);
    }
    const std::string number = std::to_string(lineNumber);
    const std::size_t numberWidth = std::max<std::size_t>(5, number.size() + 1);
    std::string out = std::string(numberWidth - number.size(), ' ') + number + " | " + shown + "\n" +
                      std::string(numberWidth, ' ') + " | ";
    // The caret line keeps the tabs of the text before the column; UTF-8 continuation bytes take no
    // place on screen.
    for (int i = 0; i + 1 < caret && i < static_cast<int>(shown.size()); ++i) {
        const unsigned char c = static_cast<unsigned char>(shown[i]);
        if (c == '\t') out += '\t';
        else if ((c & 0xC0) != 0x80) out += ' ';
    }
    out += '^';
    if (width > 1) out += std::string(static_cast<std::size_t>(width - 1), '~');
    out += '\n';
    return out;
}

TextPlace placeOfOffset(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    TextPlace place;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i)
        if (text[i] == '\n') {
            ++place.line;
            lineStart = i + 1;
        }
    std::size_t lineEnd = text.find('\n', lineStart);
    if (lineEnd == std::string_view::npos) lineEnd = text.size();
    if (lineEnd > lineStart && text[lineEnd - 1] == '\r') --lineEnd;
    place.lineText = text.substr(lineStart, lineEnd - lineStart);
    place.column = static_cast<int>(offset - lineStart) + 1;
    return place;
}

}  // namespace toyhost
