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

// How tightly a GLSL binary operator binds (11 `* / %`, 10 `+ -`, 9 `<< >>`, 8 relational,
// 7 `== !=`, 6 `&`, 5 `^`, 4 `|`, 3 `&&`, 2 `^^`, 1 `||`); 0 for every other token. For the
// precedence-climbing readers of shader/ (IntegerConstantFold, ExpressionDepth).
int glslBinaryStrength(std::string_view op);
inline constexpr int kGlslMultiplicative = 11;
inline constexpr int kGlslShift = 9;

bool isIdentifierStart(char c);
bool isIdentifierChar(char c);

}  // namespace toyhost
