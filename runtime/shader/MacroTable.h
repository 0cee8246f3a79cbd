// MacroTable: the `#define`s of a GLSL text as the rewrite's readers need them (shader/GlslRewrite.h):
// a macro's parameters and body tokens, and one invocation's replacement, so that a rule reaches
// what the browser sees after preprocessing (an index in a macro body, a declaration made by a
// macro, a constant operand written as a macro). Pure text work over shader/GlslTokens; no GL.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string_view>
#include <vector>

#include "shader/GlslTokens.h"

namespace toyhost {

struct Macro {
    bool functionLike = false;
    std::vector<std::string_view> parameters;
    std::vector<GlslToken> body;  // copies of the body's tokens (their `directive` flags cleared)
    std::size_t bodyFirst = 0;    // the index of the body's first token in the tokenized text
};

class MacroTable {
public:
    // Every `#define` of `tokens`. A name defined twice with different bodies, or named by an
    // `#undef`, is not kept: which definition the browser sees depends on conditionals.
    explicit MacroTable(const std::vector<GlslToken>& tokens);

    const Macro* find(std::string_view name) const;
    bool empty() const { return macros_.empty(); }
    const std::map<std::string_view, Macro>& all() const { return macros_; }

    // The replacement of the invocation of `macro` at tokens[at] (its name) inside `tokens` (one
    // level: the body with each parameter replaced by its argument's tokens), and the index past
    // the invocation; nothing for a function-like macro without its parenthesised arguments or with
    // the wrong number of them.
    struct Expansion {
        std::vector<GlslToken> tokens;
        std::size_t end = 0;
    };
    static std::optional<Expansion> expand(const Macro& macro, const std::vector<GlslToken>& tokens, std::size_t at);

private:
    std::map<std::string_view, Macro> macros_;
};

}  // namespace toyhost
