// GlslTokens: a small GLSL tokenizer for source rewrites (shader/GlslRewrite.h): identifiers,
// numbers and punctuation with their byte offsets, comments skipped, preprocessor lines kept as
// tokens flagged `directive`. Not a full lexer: enough to find declarations. No GL needed.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace toyhost {

struct GlslToken {
    enum class Kind { Identifier, Number, Punct };
    Kind kind = Kind::Punct;
    std::size_t offset = 0;       // into the tokenized text
    std::string_view text;        // `=`, `==`, `{`, `vec3`, `1.0e3`, ...
    bool directive = false;       // part of a `#...` line (with its `\` continuations)
    bool directiveStart = false;  // the `#` that opens such a line
};

std::vector<GlslToken> tokenizeGlsl(std::string_view text);

bool isIdentifierStart(char c);
bool isIdentifierChar(char c);

}  // namespace toyhost
