#include "shader/GlslRewrite.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "shader/FloatConstantFold.h"
#include "shader/GlslTokens.h"
#include "shader/IndexClamp.h"
#include "shader/IntegerConstantFold.h"
#include "shader/MacroTable.h"
#include "shader/OpaqueDivisors.h"

namespace toyhost {

namespace {

using Kind = GlslToken::Kind;

const std::set<std::string_view>& builtinTypes() {
    static const std::set<std::string_view> types = {
        "float", "int", "uint", "bool", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4",
        "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3",
        "mat3x4", "mat4x2", "mat4x3", "mat4x4"};
    return types;
}

bool isPrecision(std::string_view w) { return w == "highp" || w == "mediump" || w == "lowp"; }

struct Edit {
    std::size_t offset = 0;
    std::size_t erase = 0;
    std::string text;
};

// What a brace opens.
enum class Scope { Function, Block, Struct, Other };

class ZeroInitialiser {
public:
    ZeroInitialiser(const std::vector<GlslToken>& all) : macros_(all) {
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (!all[i].directive) code_.push_back(all[i]);
            // `#define NAME TYPE` on a line of its own: NAME is TYPE (a type alias).
            if (all[i].directiveStart && i + 3 < all.size() && all[i + 1].text == "define" && all[i + 2].directive &&
                all[i + 3].directive && !all[i + 3].directiveStart &&
                (i + 4 == all.size() || !all[i + 4].directive || all[i + 4].directiveStart) &&
                all[i + 2].offset + all[i + 2].text.size() < all[i + 3].offset)  // not `NAME(`
                aliases_[all[i + 2].text] = all[i + 3].text;
        }
    }

    // The edits, or none when the braces do not balance.
    bool run(std::vector<Edit>& edits) {
        int nesting = 0;  // ( and [
        declaration(0);
        for (std::size_t k = 0; k < code_.size(); ++k) {
            const std::string_view t = code_[k].text;
            if (t == "(" || t == "[") {
                ++nesting;
                // A for-init declaration is executed at every execution of the loop, as the
                // browser zeroes it (a `for (float t; ...)` in a function called 3 times).
                if (t == "(" && k > 0 && code_[k - 1].text == "for" && inCode()) declaration(k + 1, true);
            } else if (t == ")" || t == "]") {
                if (--nesting < 0) return false;
            } else if (t == "{") {
                const std::string_view prev = k > 0 ? code_[k - 1].text : std::string_view{};
                Scope scope = Scope::Other;
                std::string_view structName;
                if (k > 0 && prev == "struct") scope = Scope::Struct;
                else if (k > 1 && code_[k - 1].kind == Kind::Identifier && code_[k - 2].text == "struct")
                    scope = Scope::Struct, structName = prev;
                else if (stack_.empty() && prev == ")") scope = Scope::Function;
                else if (!stack_.empty() && inCode()) scope = Scope::Block;
                stack_.push_back({scope, structName, k});
                if (scope == Scope::Function) zeroOutParameters(k);
                if (scope == Scope::Function || scope == Scope::Block) declaration(k + 1);
            } else if (t == "}") {
                if (stack_.empty()) return false;
                const Frame closed = stack_.back();
                stack_.pop_back();
                if (closed.scope == Scope::Struct && !closed.name.empty() && (stack_.empty() || inCode()))
                    zeroFunction(closed, k);
                if ((inCode() || (stack_.empty() && closed.scope == Scope::Function)) && nesting == 0) declaration(k + 1);
            } else if ((t == ";" || t == ":") && nesting == 0 && inCode()) {
                declaration(k + 1);
            } else if (t == ";" && nesting == 0 && stack_.empty()) {
                declaration(k + 1);
            }
        }
        if (!stack_.empty() || nesting != 0) return false;
        edits.insert(edits.end(), edits_.begin(), edits_.end());
        return true;
    }

private:
    struct Frame {
        Scope scope;
        std::string_view name;
        std::size_t open = 0;  // the index of its `{`
    };

    bool inCode() const {
        return !stack_.empty() && (stack_.back().scope == Scope::Function || stack_.back().scope == Scope::Block);
    }

    static std::string zeroName(std::string_view structName) { return "toyhost_z" + std::string(structName); }

    // A struct whose `}` is at `close`: when every member's type is known, it becomes a known type.
    // A global one gets a function returning its zero value, defined right after the
    // declaration's `;` (the driver's zero-initialisation of a global struct cannot be relied on:
    // llvmpipe leaves one undefined). A struct defined in a function body, where no function can
    // be defined, is zeroed by its constructor with every member zero; one with an array member
    // is left to the driver.
    void zeroFunction(const Frame& frame, std::size_t close) {
        std::string body;
        std::string constructor;
        bool hasArray = false;
        for (std::size_t k = frame.open + 1; k < close;) {
            while (k < close && isPrecision(code_[k].text)) ++k;
            if (k >= close) break;
            const std::string zero = zeroOf(code_[k].text);
            if (zero.empty()) return;
            ++k;
            bool typeArray = false;
            if (k < close && code_[k].text == "[") typeArray = true, k = skipBrackets(k);
            while (k < close) {
                if (code_[k].kind != Kind::Identifier) return;
                const std::string member = "z." + std::string(code_[k++].text);
                bool array = typeArray;
                if (k < close && code_[k].text == "[") array = true, k = skipBrackets(k);
                if (k >= close) return;
                body += array ? zeroLoop(member, zero) : member + "=" + zero + ";";
                constructor += (constructor.empty() ? "" : ",") + zero;
                hasArray = hasArray || array;
                if (code_[k++].text == ";") break;
            }
        }
        const std::string name(frame.name);
        if (!stack_.empty()) {
            if (hasArray || constructor.empty()) return;
            structs_[frame.name] = name + "(" + constructor + ")";
            return;
        }
        std::size_t semicolon = close + 1;
        while (semicolon < code_.size() && code_[semicolon].text != ";") ++semicolon;
        if (semicolon >= code_.size()) return;
        add(end(semicolon), " " + name + " " + zeroName(name) + "(){" + name + " z;" + body + "return z;}");
        structs_[frame.name] = zeroName(name) + "()";
    }

    // The zero value of a type, or empty when the type is not known.
    std::string zeroOf(std::string_view type) const {
        if (auto alias = aliases_.find(type); alias != aliases_.end()) type = alias->second;
        if (builtinTypes().count(type)) return std::string(type) + "(0)";
        if (auto known = structs_.find(type); known != structs_.end()) return known->second;
        return {};
    }

    static std::string zeroLoop(std::string_view name, const std::string& zero) {
        const std::string n(name);
        return "for(int toyhost_i=0;toyhost_i<" + n + ".length();++toyhost_i)" + n + "[toyhost_i]=" + zero + ";";
    }

    void add(std::size_t offset, std::string text) { edits_.push_back({offset, 0, std::move(text)}); }

    std::size_t end(std::size_t k) const { return code_[k].offset + code_[k].text.size(); }

    // The index after the `]` that matches the `[` at `k` (code_.size() when unmatched).
    std::size_t skipBrackets(std::size_t k) const {
        int depth = 0;
        for (; k < code_.size(); ++k) {
            if (code_[k].text == "[" || code_[k].text == "(") ++depth;
            else if ((code_[k].text == "]" || code_[k].text == ")") && --depth == 0) return k + 1;
        }
        return code_.size();
    }

    // A declaration statement starting at `k` (`[precision] TYPE[[n]] name[[n]] [= init], ...;`):
    // each declarator without an initialiser gets one. Anything else is left alone.
    // In a for-init (`forInit`), arrays, whose zeroing loop cannot go there, are left alone.
    void declaration(std::size_t k, bool forInit = false) {
        const std::size_t n = code_.size();
        while (k < n && (isPrecision(code_[k].text) || code_[k].text == "precise")) ++k;
        if (k >= n || code_[k].kind != Kind::Identifier) return;
        const std::string zero = zeroOf(code_[k].text);
        if (zero.empty()) {
            if (const Macro* macro = macros_.find(code_[k].text); macro && !forInit && inCode()) macroDeclaration(k, *macro);
            return;
        }
        const bool global = stack_.empty();
        const bool builtin = builtinTypes().count(zero.substr(0, zero.find('('))) > 0;
        std::string pending;  // for globals_, once the statement reads as a declaration
        ++k;
        bool typeArray = false;
        if (k < n && code_[k].text == "[") typeArray = true, k = skipBrackets(k);
        std::vector<Edit> found;
        std::vector<std::string_view> arrays;
        while (true) {
            if (k >= n || code_[k].kind != Kind::Identifier) return;
            const std::string_view name = code_[k++].text;
            bool array = typeArray;
            if (k < n && code_[k].text == "[") array = true, k = skipBrackets(k);
            if (k >= n) return;
            if (code_[k].text == "=") {
                int depth = 0;
                for (++k; k < n; ++k) {
                    const std::string_view t = code_[k].text;
                    if (t == "(" || t == "[") ++depth;
                    else if (t == ")" || t == "]") --depth;
                    else if (depth == 0 && (t == "," || t == ";")) break;
                    else if (t == "{" || t == "}") return;
                }
                if (k >= n) return;
            } else if (code_[k].text == "," || code_[k].text == ";") {
                // A global's initialiser must be constant: arrays and structs are zeroed when the
                // entry function starts (once per invocation, as WebGL initialises globals).
                if (global && (array || !builtin)) pending += array ? zeroLoop(name, zero) : std::string(name) + "=" + zero + ";";
                else if (array) arrays.push_back(name);
                else found.push_back({end(k - 1), 0, "=" + zero});
            } else {
                return;  // not a declaration
            }
            if (code_[k].text == ";") break;
            ++k;
        }
        if (forInit && !arrays.empty()) return;
        std::string loops;
        for (std::string_view a : arrays) loops += zeroLoop(a, zero);
        if (!loops.empty()) found.push_back({end(k), 0, loops});
        edits_.insert(edits_.end(), found.begin(), found.end());
        globals_ += pending;
    }

    // A statement at `k` that starts with the invocation of `macro`: when its expansion (with the
    // statement's rest, up to its `;`) declares locals without an initialiser, they are set to zero
    // right after the statement, as the browser, which sees the expanded text, zeroes them
    // (`#define ACC float acc;` or `#define LOCAL(t, n) t n` ... `LOCAL(float, acc);`).
    void macroDeclaration(std::size_t k, const Macro& macro) {
        const std::optional<MacroTable::Expansion> expansion = MacroTable::expand(macro, code_, k);
        if (!expansion) return;
        std::vector<std::string_view> words;
        for (const GlslToken& t : expansion->tokens) words.push_back(t.text);
        std::size_t after = end(expansion->end - 1);
        const auto semicolon = std::find(words.begin(), words.end(), ";");
        if (semicolon == words.end()) {
            std::size_t j = expansion->end;
            for (int depth = 0; j < code_.size(); ++j) {
                const std::string_view t = code_[j].text;
                if (t == "{" || t == "}") return;
                if (t == "(" || t == "[") ++depth;
                else if (t == ")" || t == "]") --depth;
                else if (t == ";" && depth == 0) break;
                words.push_back(t);
            }
            if (j >= code_.size()) return;
            words.push_back(";");
            after = end(j);
        } else if (words.back() != ";") {
            return;  // a statement the body leaves open and the text completes: not read
        }
        std::string zeroing;
        for (std::size_t from = 0; from < words.size();) {
            std::size_t to = from;
            while (words[to] != ";") ++to;
            zeroing += zeroedDeclarators(words, from, to);
            from = to + 1;
        }
        if (!zeroing.empty()) add(after, " " + zeroing);
    }

    // The zeroing statements of the declarators of `words[from, to)` that have no initialiser, when
    // those words are a declaration of a known type; empty otherwise.
    std::string zeroedDeclarators(const std::vector<std::string_view>& words, std::size_t k, std::size_t to) const {
        auto skipBrackets = [&](std::size_t j) {
            for (int depth = 0; j < to; ++j) {
                if (words[j] == "[" || words[j] == "(") ++depth;
                else if ((words[j] == "]" || words[j] == ")") && --depth == 0) return j + 1;
            }
            return to;
        };
        auto isName = [](std::string_view w) { return !w.empty() && isIdentifierStart(w[0]); };
        while (k < to && (isPrecision(words[k]) || words[k] == "precise")) ++k;
        if (k >= to) return {};
        const std::string zero = zeroOf(words[k]);
        if (zero.empty()) return {};
        std::string out;
        bool typeArray = false;
        if (++k < to && words[k] == "[") typeArray = true, k = skipBrackets(k);
        while (true) {
            if (k >= to || !isName(words[k])) return {};
            const std::string_view name = words[k++];
            bool array = typeArray;
            if (k < to && words[k] == "[") array = true, k = skipBrackets(k);
            if (k < to && words[k] == "=") {
                for (int depth = 0; k < to; ++k) {
                    if (words[k] == "(" || words[k] == "[") ++depth;
                    else if (words[k] == ")" || words[k] == "]") --depth;
                    else if (depth == 0 && words[k] == ",") break;
                }
            } else if (k < to && words[k] != ",") {
                return {};  // not a declaration
            } else {
                out += array ? zeroLoop(name, zero) : std::string(name) + "=" + zero + ";";
            }
            if (k >= to) return out;
            ++k;
        }
    }

    // A function definition whose `{` is at `brace`: each `out` parameter is set to zero first.
    void zeroOutParameters(std::size_t brace) {
        std::size_t open = brace - 1;
        for (int depth = 0;; --open) {
            if (code_[open].text == ")") ++depth;
            else if (code_[open].text == "(" && --depth == 0) break;
            if (open == 0) return;
        }
        std::string zeroing;
        std::size_t k = open + 1;
        while (k < brace - 1) {
            std::size_t stop = k;
            for (int depth = 0; stop < brace - 1; ++stop) {
                const std::string_view t = code_[stop].text;
                if (t == "(" || t == "[") ++depth;
                else if (t == ")" || t == "]") --depth;
                else if (t == "," && depth == 0) break;
            }
            bool out = false;
            std::size_t i = k;
            for (; i < stop; ++i) {
                const std::string_view t = code_[i].text;
                if (t == "out") out = true;
                else if (!(t == "in" || t == "inout" || t == "const" || isPrecision(t))) break;
            }
            if (out && i + 1 < stop) {
                const std::string zero = zeroOf(code_[i].text);
                bool array = false;
                std::string_view name;
                for (std::size_t j = i + 1; j < stop; ++j) {
                    if (code_[j].text == "[") array = true;
                    else if (code_[j].kind == Kind::Identifier && name.empty() && !array) name = code_[j].text;
                    else if (code_[j].kind == Kind::Identifier && name.empty() && code_[j - 1].text == "]") name = code_[j].text;
                }
                if (!zero.empty() && !name.empty())
                    zeroing += array ? zeroLoop(name, zero) : std::string(name) + "=" + zero + ";";
            }
            k = stop + 1;
        }
        const std::string_view function = open > 0 ? code_[open - 1].text : std::string_view{};
        if (function == "mainImage" || function == "mainCubemap" || function == "mainSound") zeroing += globals_;
        if (!zeroing.empty()) add(end(brace), zeroing);
    }

    std::vector<GlslToken> code_;
    MacroTable macros_;
    std::map<std::string_view, std::string_view> aliases_;
    std::map<std::string_view, std::string> structs_;  // a known struct's zero value
    std::vector<Frame> stack_;
    std::vector<Edit> edits_;
    std::string globals_;  // zeroing of the global arrays and structs declared so far
};

// True for each token that is, or may be, part of an expression GLSL requires to be constant:
// everything outside function bodies (global initialisers, which GLSL ES 3.00 requires to be
// constant, and array sizes of globals, members and parameters), a `const` declaration in a body,
// and the array size of a local declaration (`float a[...]`, `T a[...]`). A call of a user
// function is never constant, so there the precise asin/acos cannot be called.
std::vector<bool> constantContexts(const std::vector<GlslToken>& tokens) {
    std::vector<bool> constant(tokens.size(), false);
    int braces = 0;
    bool constStatement = false;
    int parens = 0;         // ( depth inside a const statement
    std::size_t sizeUntil = 0;  // inside an array size up to this token
    auto isWord = [&](std::size_t j) {
        const std::string_view w = tokens[j].text;
        return tokens[j].kind == Kind::Identifier && w != "return" && w != "else" && w != "case" && w != "do";
    };
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const GlslToken& t = tokens[i];
        if (t.directive) continue;
        if (t.text == "{") ++braces;
        else if (t.text == "}") braces = std::max(0, braces - 1);
        if (braces == 0 || i < sizeUntil) {
            constant[i] = true;
            continue;
        }
        if (t.text == "const") constStatement = true, parens = 0;
        if (constStatement) {
            constant[i] = true;
            if (t.text == "(") ++parens;
            else if (t.text == ")") --parens;
            else if ((t.text == ";" && parens <= 0) || t.text == "{" || t.text == "}") constStatement = false;
            continue;
        }
        if (t.text == "[" && i > 0 && (builtinTypes().count(tokens[i - 1].text) || (i > 1 && isWord(i - 1) && isWord(i - 2)))) {
            int depth = 0;
            std::size_t j = i;
            for (; j < tokens.size(); ++j) {
                if (tokens[j].text == "[") ++depth;
                else if (tokens[j].text == "]" && --depth == 0) break;
            }
            sizeUntil = j;
            constant[i] = true;
        }
    }
    return constant;
}

// `asin(x)` / `acos(x)` of a float literal at `i` (the name's index): the value ANGLE's constant
// folder gives it (C's asinf / acosf), as a literal, and the index of the `)`; nothing when the
// call is not of that shape or x is outside [-1, 1] (left to the driver).
std::optional<std::pair<std::string, std::size_t>> foldedInverseTrig(const std::vector<GlslToken>& tokens, std::size_t i) {
    std::size_t k = i + 1;
    if (k >= tokens.size() || tokens[k].text != "(") return std::nullopt;
    ++k;
    bool negative = false;
    if (k < tokens.size() && (tokens[k].text == "-" || tokens[k].text == "+")) negative = tokens[k++].text == "-";
    if (k + 1 >= tokens.size() || tokens[k].kind != Kind::Number || tokens[k + 1].text != ")") return std::nullopt;
    const std::string literal(tokens[k].text);
    if (literal.find_first_of("xX") != std::string::npos || literal.find_first_of(".eE") == std::string::npos)
        return std::nullopt;  // an int: no implicit conversion in GLSL ES, the driver says so
    float x = std::strtof(literal.c_str(), nullptr);
    if (negative) x = -x;
    if (!(x >= -1.0f && x <= 1.0f)) return std::nullopt;
    const float value = tokens[i].text == "asin" ? std::asin(x) : std::acos(x);
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
    std::string out = text;
    if (out.find_first_of(".e") == std::string::npos) out += ".0";
    if (value < 0.0f || std::signbit(value)) out = "(" + out + ")";  // never `x--0.5`
    return std::make_pair(out, k + 1);
}

}  // namespace

const char* rewriteRuleName(RewriteRule rule) {
    switch (rule) {
        case RewriteRule::ZeroInit: return "zeroInit";
        case RewriteRule::ClampIndices: return "clampIndices";
        case RewriteRule::FoldIntegerConstants: return "foldIntegerConstants";
        case RewriteRule::FoldFloatConstants: return "foldFloatConstants";
        case RewriteRule::PreciseInverseTrig: return "preciseInverseTrig";
        case RewriteRule::OpaqueDivisors: return "opaqueDivisors";
        case RewriteRule::Rename: return "rename";
    }
    return "";
}

const char* rewriteRuleEffect(RewriteRule rule) {
    switch (rule) {
        case RewriteRule::ZeroInit: return "locals, out parameters and globals are not zeroed as WebGL zeroes them";
        case RewriteRule::ClampIndices: return "dynamic indices are not clamped into range as WebGL clamps them";
        case RewriteRule::FoldIntegerConstants:
            return "undefined integer constant operations keep the driver's values, not the browser's";
        case RewriteRule::FoldFloatConstants:
            return "constant float built-ins with undefined arguments and constant round() keep the driver's values, not the browser's";
        case RewriteRule::PreciseInverseTrig: return "asin and acos are the driver's, less precise than the browser's";
        case RewriteRule::OpaqueDivisors:
            return "a division by a zero the compiler can see gives the driver's folded value, not IEEE's";
        case RewriteRule::Rename: return "words Mesa reserves (packed, dmat2...) are not renamed";
    }
    return "";
}

bool& ruleSwitch(GlslRewriteOptions& options, RewriteRule rule) {
    switch (rule) {
        case RewriteRule::ZeroInit: return options.zeroInit;
        case RewriteRule::ClampIndices: return options.clampIndices;
        case RewriteRule::FoldIntegerConstants: return options.foldIntegerConstants;
        case RewriteRule::FoldFloatConstants: return options.foldFloatConstants;
        case RewriteRule::PreciseInverseTrig: return options.preciseInverseTrig;
        case RewriteRule::OpaqueDivisors: return options.opaqueDivisors;
        case RewriteRule::Rename: break;
    }
    return options.rename;
}

// Every GLSL ES 3.00 reserved and extension word compiled as a local's name on both sides
// (webref, headless Chromium with ANGLE, against Mesa 22.3): these are the ones browsers accept
// and Mesa refuses. The rest are refused by both (dvec2, union, ...) or accepted by both.
std::string_view webglOnlyIdentifierRename(std::string_view word) {
    static const std::map<std::string_view, std::string_view> renames = {
        {"packed", "toyhost_packed"},   {"dmat2", "toyhost_dmat2"},     {"dmat3", "toyhost_dmat3"},
        {"dmat4", "toyhost_dmat4"},     {"dmat2x2", "toyhost_dmat2x2"}, {"dmat2x3", "toyhost_dmat2x3"},
        {"dmat2x4", "toyhost_dmat2x4"}, {"dmat3x2", "toyhost_dmat3x2"}, {"dmat3x3", "toyhost_dmat3x3"},
        {"dmat3x4", "toyhost_dmat3x4"}, {"dmat4x2", "toyhost_dmat4x2"}, {"dmat4x3", "toyhost_dmat4x3"},
        {"dmat4x4", "toyhost_dmat4x4"}};
    const auto found = renames.find(word);
    return found == renames.end() ? std::string_view{} : found->second;
}

std::string rewriteLikeWebGL(std::string_view text, GlslRewriteOptions promote) {
    const std::vector<GlslToken> tokens = tokenizeGlsl(text);
    std::vector<Edit> edits;
    std::vector<bool> constant;
    if (promote.preciseInverseTrig) constant = constantContexts(tokens);
    std::size_t directiveAt = 0;  // the index of the `#` of the current directive line
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const GlslToken& t = tokens[i];
        if (t.directiveStart) directiveAt = i;
        if (t.kind != Kind::Identifier) continue;
        if (std::string_view to = webglOnlyIdentifierRename(t.text); promote.rename && !to.empty())
            edits.push_back({t.offset, t.text.size(), std::string(to)});
        if (promote.preciseInverseTrig && (t.text == "asin" || t.text == "acos")) {
            if (auto folded = foldedInverseTrig(tokens, i)) {
                const GlslToken& close = tokens[folded->second];
                edits.push_back({t.offset, close.offset + close.text.size() - t.offset, std::move(folded->first)});
                i = folded->second;
                continue;
            }
            if (!constant[i]) edits.push_back({t.offset, 0, "toyhost_"});
        }
        if (!promote.fragCoord.empty() && t.text == "gl_FragCoord")
            edits.push_back({t.offset, t.text.size(), std::string(promote.fragCoord)});
        const bool promoted = (t.text == "lowp" && promote.lowp) || (t.text == "mediump" && promote.mediump);
        if (promoted && (!t.directive || (directiveAt + 1 < i && tokens[directiveAt + 1].text == "define" && i > directiveAt + 2)))
            edits.push_back({t.offset, t.text.size(), "highp"});
    }
    if (promote.zeroInit) ZeroInitialiser(tokens).run(edits);
    if (promote.clampIndices)
        for (IndexInsertion& insertion : clampDynamicIndices(tokens)) edits.push_back({insertion.offset, 0, std::move(insertion.text)});
    if (promote.foldIntegerConstants)
        for (ConstantFoldEdit& fold : foldUndefinedIntegerConstants(tokens))
            edits.push_back({fold.offset, fold.erase, std::move(fold.text)});
    if (promote.foldFloatConstants)
        for (ConstantFoldEdit& fold : foldAngleFloatBuiltins(tokens)) edits.push_back({fold.offset, fold.erase, std::move(fold.text)});
    if (promote.opaqueDivisors) {
        std::vector<Edit> opening;
        for (DivisorInsertion& divisor : opaqueDivisors(tokens))
            (divisor.closes ? edits : opening).push_back({divisor.offset, 0, std::move(divisor.text)});
        edits.insert(edits.begin(), opening.begin(), opening.end());
    }
    std::stable_sort(edits.begin(), edits.end(), [](const Edit& a, const Edit& b) {
        return a.offset != b.offset ? a.offset < b.offset : a.erase < b.erase;  // insertions first
    });
    std::string out;
    out.reserve(text.size() + edits.size() * 16);
    std::size_t at = 0;
    for (const Edit& e : edits) {
        if (e.offset < at) continue;  // never overlaps; kept safe
        out.append(text.substr(at, e.offset - at));
        out += e.text;
        at = e.offset + e.erase;
    }
    out.append(text.substr(at));
    if (promote.plantedFailure && ruleSwitch(promote, *promote.plantedFailure))
        out += std::string(out.empty() || out.back() == '\n' ? "" : "\n") + "float toyhost_planted = toyhost_planted_failure_of_" + rewriteRuleName(*promote.plantedFailure) + ";";
    return out;
}

}  // namespace toyhost
