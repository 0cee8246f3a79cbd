#include "shader/ExpressionDepth.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "shader/GlslTokens.h"

namespace toyhost {

namespace {

// GLSL's binary operator precedence classes (1 = multiplicative .. 12 = assignment); 0 for others.
int precedence(std::string_view op) {
    static const std::map<std::string_view, int> classes = {
        {"*", 1},  {"/", 1},  {"%", 1},   {"+", 2},  {"-", 2},  {"<<", 3}, {">>", 3}, {"<", 4},  {">", 4},
        {"<=", 4}, {">=", 4}, {"==", 5},  {"!=", 5}, {"&", 6},  {"^", 7},  {"|", 8},  {"&&", 9}, {"^^", 10},
        {"||", 11}, {"?", 12}, {"=", 13}, {"+=", 13}, {"-=", 13}, {"*=", 13}, {"/=", 13}};
    const auto found = classes.find(op);
    return found == classes.end() ? 0 : found->second;
}

struct Level {
    std::array<int, 14> counts{};
    int deepestChild = 0;
    int deepestItem = 0;  // of the items (arguments) already closed by a comma
    bool node = false;    // a call, constructor or index (one tree level); bare parentheses are none

    int item() const {
        int longest = 0, classes = 0;
        for (int c : counts)
            if (c) longest = std::max(longest, c), ++classes;
        return longest + std::max(0, classes - 1) + deepestChild;
    }
    int depth() const { return std::max(deepestItem, item()); }
    void nextItem() {
        deepestItem = std::max(deepestItem, item());
        counts = {};
        deepestChild = 0;
    }
};

}  // namespace

DeepestStatement deepestStatement(std::string_view code) {
    DeepestStatement deepest;
    std::vector<Level> levels(1);
    std::size_t statementStart = 0;
    bool fresh = true;  // the next token starts a statement
    auto endStatement = [&] {
        const int depth = levels.front().depth();
        if (depth > deepest.depth) {
            deepest.depth = depth;
            deepest.line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + statementStart, '\n'));
        }
        levels.assign(1, Level{});
        fresh = true;
    };
    bool operandBefore = false;  // a binary operator needs an operand on its left; `(` after one is a call
    for (const GlslToken& t : tokenizeGlsl(code)) {
        if (t.directive) continue;
        const std::string_view w = t.text;
        if (fresh) statementStart = t.offset, fresh = false;
        if (w == "(" || w == "[") {
            levels.emplace_back();
            levels.back().node = w == "[" || operandBefore;
            operandBefore = false;
        } else if ((w == ")" || w == "]") && levels.size() > 1) {
            const int depth = levels.back().depth() + (levels.back().node ? 1 : 0);
            levels.pop_back();
            levels.back().deepestChild = std::max(levels.back().deepestChild, depth);
            operandBefore = true;
        } else if (w == ";" || w == "{" || w == "}") {
            endStatement();
            operandBefore = false;
        } else if (w == ",") {
            levels.back().nextItem();
            operandBefore = false;
        } else if (const int p = precedence(w); p && operandBefore) {
            ++levels.back().counts[p];
            operandBefore = false;
        } else if (t.kind != GlslToken::Kind::Punct) {
            operandBefore = true;
        }
    }
    endStatement();
    return deepest;
}

namespace {

// A lower bound of the depth of ANGLE's tree for an expression: a leaf is 1, an operation 1 more
// than its deepest operand, and an operation on constants alone is one constant (ANGLE folds it
// while parsing). Parentheses are no level. What it cannot read ends the expression there.
struct Node {
    int depth = 1;
    bool constant = false;
};

Node operation(std::initializer_list<Node> operands) {
    Node n;
    bool constant = true;
    int deepest = 0;
    for (const Node& o : operands) constant = constant && o.constant, deepest = std::max(deepest, o.depth);
    if (constant) return Node{1, true};
    n.depth = deepest + 1;
    return n;
}

bool isAssignment(std::string_view op) {
    return op == "=" || op == "+=" || op == "-=" || op == "*=" || op == "/=" || op == "%=" || op == "&=" || op == "|=" ||
           op == "^=";
}

bool isStatementWord(std::string_view w) {
    static const std::set<std::string_view> words = {"return", "if", "else", "for", "while", "do", "switch", "case",
                                                     "default", "break", "continue", "discard", "struct", "const",
                                                     "uniform", "in", "out", "inout", "precision", "highp", "mediump",
                                                     "lowp"};
    return words.count(w) != 0;
}

class LowerBound {
public:
    LowerBound(const std::vector<GlslToken>& tokens, const std::set<std::string_view>& constants)
        : t_(tokens), constants_(constants) {}

    // The expression at `at` without top-level commas; `at` moves past it.
    std::optional<Node> assignment(std::size_t& at) const {
        std::optional<Node> left = conditional(at);
        if (!left || at >= t_.size() || t_[at].directive || !isAssignment(t_[at].text)) return left;
        ++at;
        std::optional<Node> right = assignment(at);
        if (!right) return std::nullopt;
        return Node{std::max(left->depth, right->depth) + 1, false};
    }

private:
    bool is(std::size_t at, std::string_view text) const {
        return at < t_.size() && !t_[at].directive && t_[at].text == text;
    }

    std::optional<Node> expression(std::size_t& at) const {
        std::optional<Node> left = assignment(at);
        while (left && is(at, ",")) {
            ++at;
            std::optional<Node> right = assignment(at);
            if (!right) return std::nullopt;
            left = operation({*left, *right});
        }
        return left;
    }

    std::optional<Node> conditional(std::size_t& at) const {
        std::optional<Node> c = binary(at, 1);
        if (!c || !is(at, "?")) return c;
        ++at;
        std::optional<Node> a = expression(at);
        if (!a || !is(at, ":")) return std::nullopt;
        ++at;
        std::optional<Node> b = assignment(at);
        if (!b) return std::nullopt;
        // ANGLE keeps only the chosen branch of a constant condition: either may be the one.
        if (c->constant) return Node{std::min(a->depth, b->depth), a->constant && b->constant};
        return operation({*c, *a, *b});
    }

    std::optional<Node> binary(std::size_t& at, int minStrength) const {
        std::optional<Node> left = unary(at);
        while (left && at < t_.size() && !t_[at].directive) {
            const int strength = glslBinaryStrength(t_[at].text);
            if (strength == 0 || strength < minStrength) break;
            ++at;
            std::optional<Node> right = binary(at, strength + 1);
            if (!right) return std::nullopt;
            left = operation({*left, *right});
        }
        return left;
    }

    std::optional<Node> unary(std::size_t& at) const {
        // Every nesting passes here. Far past any limit, or past the time budget, the text is left
        // unread (the estimate's warning still speaks for it): stack and time stay small on any text.
        if (nesting_ > kMostNesting || ++steps_ > stepBudget_) return tooDeep_ = true, std::nullopt;
        struct Nested {
            int& n;
            explicit Nested(int& level) : n(++level) {}
            ~Nested() { --n; }
        } nested(nesting_);
        if (is(at, "-") || is(at, "!") || is(at, "~")) {
            ++at;
            std::optional<Node> operand = unary(at);
            if (!operand) return std::nullopt;
            return operation({*operand});
        }
        if (is(at, "+")) {
            ++at;
            return unary(at);
        }
        if (is(at, "++") || is(at, "--")) {
            ++at;
            std::optional<Node> operand = unary(at);
            if (!operand) return std::nullopt;
            return Node{operand->depth + 1, false};
        }
        return postfix(at);
    }

    std::optional<Node> postfix(std::size_t& at) const {
        std::optional<Node> n = primary(at);
        while (n) {
            if (is(at, ".") && at + 1 < t_.size() && t_[at + 1].kind == GlslToken::Kind::Identifier) {
                at += 2;
                n = operation({*n});
            } else if (is(at, "[")) {
                ++at;
                std::optional<Node> index = expression(at);
                if (!index || !is(at, "]")) return std::nullopt;
                ++at;
                n = operation({*n, *index});
            } else if (is(at, "++") || is(at, "--")) {
                ++at;
                n = Node{n->depth + 1, false};
            } else {
                break;
            }
        }
        return n;
    }

    std::optional<Node> primary(std::size_t& at) const {
        if (at >= t_.size() || t_[at].directive) return std::nullopt;
        const GlslToken& first = t_[at];
        if (first.kind == GlslToken::Kind::Number) {
            ++at;
            return Node{1, true};
        }
        if (first.text == "(") {
            ++at;
            std::optional<Node> inner = expression(at);
            if (!inner || !is(at, ")")) return std::nullopt;
            ++at;
            return inner;
        }
        if (first.kind != GlslToken::Kind::Identifier || isStatementWord(first.text)) return std::nullopt;
        ++at;
        if (!is(at, "(")) return Node{1, first.text == "true" || first.text == "false" || constants_.count(first.text) != 0};
        // A call or a constructor: one node over its arguments; with constant arguments alone it may
        // be folded (a constructor, a built-in) or be a macro, so it counts as a constant.
        ++at;
        Node call{1, true};
        bool first_argument = true;
        while (!is(at, ")")) {
            if (!first_argument) {
                if (!is(at, ",")) return std::nullopt;
                ++at;
            }
            if (first_argument && is(at, "void")) {
                ++at;
                first_argument = false;
                continue;
            }
            std::optional<Node> argument = assignment(at);
            if (!argument) return std::nullopt;
            call = Node{std::max(call.depth, argument->depth + 1), call.constant && argument->constant};
            first_argument = false;
        }
        ++at;
        if (call.constant) return Node{1, true};
        return call;
    }

    static constexpr int kMostNesting = 1024;
    const std::vector<GlslToken>& t_;
    const std::set<std::string_view>& constants_;
    mutable int nesting_ = 0;
    mutable std::size_t steps_ = 0;
    std::size_t stepBudget_ = 64 * t_.size() + 100000;  // a few per token is plenty for real code

public:
    // Whether a read stopped at the nesting guard (cleared by the caller).
    mutable bool tooDeep_ = false;
};

}  // namespace

DeepestStatement deepestStatementAtLeast(std::string_view code) {
    const std::vector<GlslToken> tokens = tokenizeGlsl(code);
    // Names that may stand for a constant: `const` declarations, and every macro (its expansion is
    // unknown here).
    std::set<std::string_view> constants;
    for (std::size_t i = 0; i + 2 < tokens.size(); ++i) {
        if (tokens[i].directive && tokens[i].text == "define" && tokens[i + 1].directive) constants.insert(tokens[i + 1].text);
        if (!tokens[i].directive && tokens[i].text == "const") {
            std::size_t j = i + 1;
            while (j < tokens.size() && tokens[j].kind == GlslToken::Kind::Identifier && j + 1 < tokens.size() &&
                   tokens[j + 1].kind == GlslToken::Kind::Identifier)
                ++j;  // qualifiers and the type; j is the name
            for (; j < tokens.size() && tokens[j].text != ";"; ++j)
                if (tokens[j].kind == GlslToken::Kind::Identifier && (j == i + 1 || tokens[j - 1].text == "," ||
                                                                      tokens[j - 1].kind == GlslToken::Kind::Identifier))
                    constants.insert(tokens[j].text);
        }
    }
    const LowerBound bound(tokens, constants);
    // Braces around each token: inside a function's body its statements sit below the root, the
    // function and the body.
    std::vector<int> braces(tokens.size(), 0);
    for (std::size_t i = 0, depth = 0; i < tokens.size(); ++i) {
        if (!tokens[i].directive && tokens[i].text == "}" && depth > 0) --depth;
        braces[i] = static_cast<int>(depth);
        if (!tokens[i].directive && tokens[i].text == "{") ++depth;
    }
    auto isType = [&](std::size_t j) {
        return tokens[j].kind == GlslToken::Kind::Identifier && !isStatementWord(tokens[j].text) ? true
               : tokens[j].text == "highp" || tokens[j].text == "mediump" || tokens[j].text == "lowp";
    };
    // The levels of ANGLE's tree above an expression read from token i, at least (the root block
    // counts 0): a function's root, the function and its body (2), the declaration and its
    // initialisation for `TYPE NAME = ...` inside a body (4), an assignment whose left side was not
    // read (3); a global's initialiser sits under its declaration and initialisation (2).
    auto levelsAbove = [&](std::size_t i) {
        const bool initialiser = i > 0 && tokens[i - 1].text == "=";
        if (braces[i] == 0) return initialiser ? 2 : 0;
        if (!initialiser) return 2;
        const bool declaration = i >= 3 && tokens[i - 2].kind == GlslToken::Kind::Identifier && isType(i - 3);
        return declaration ? 4 : 3;
    };
    DeepestStatement deepest;
    std::size_t coveredTo = 0;  // a successful parse covers the starts inside it
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (i < coveredTo || tokens[i].directive) continue;
        const std::string_view before = i == 0 ? std::string_view(";") : tokens[i - 1].text;
        const bool start = before == ";" || before == "{" || before == "}" || before == "(" || before == "," ||
                           before == ")" || before == ":" || before == "?" || before == "return" || before == "else" ||
                           isAssignment(before) || (i > 0 && tokens[i - 1].directive);
        if (!start) continue;
        std::size_t at = i;
        bound.tooDeep_ = false;
        const std::optional<Node> n = bound.assignment(at);
        if (!n && bound.tooDeep_) {
            // Past the guard: every start inside would stop there too; the statement counts nothing.
            while (at < tokens.size() && tokens[at].text != ";" && tokens[at].text != "{" && tokens[at].text != "}") ++at;
            coveredTo = at;
            continue;
        }
        if (!n) continue;
        coveredTo = at;
        if (const int depth = n->depth + levelsAbove(i); depth > deepest.depth) {
            deepest.depth = depth;
            deepest.line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<std::ptrdiff_t>(tokens[i].offset), '\n'));
        }
    }
    return deepest;
}

DeepestCallChain deepestCallChain(std::string_view code) {
    const std::vector<GlslToken> tokens = tokenizeGlsl(code);
    // Top-level function definitions: `type name ( ... ) {` at brace depth 0; the calls in each body.
    std::map<std::string_view, std::set<std::string_view>> calls;
    std::map<std::string_view, std::size_t> definedAt;  // offset of the name
    std::map<std::string_view, int> definitions;       // how many functions have the name
    int braces = 0;
    std::string_view current;
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        const GlslToken& t = tokens[i];
        if (t.directive) continue;
        if (t.text == "{") {
            if (braces == 0 && i > 0 && tokens[i - 1].text == ")") {
                // Back to the parenthesis that opens the parameter list: the name is before it.
                int depth = 0;
                std::size_t j = i - 1;
                for (; j > 0; --j) {
                    if (tokens[j].text == ")") ++depth;
                    else if (tokens[j].text == "(" && --depth == 0) break;
                }
                if (j > 0 && tokens[j - 1].kind == GlslToken::Kind::Identifier) {
                    current = tokens[j - 1].text;
                    ++definitions[current];
                    calls[current];
                    definedAt.emplace(current, tokens[j - 1].offset);
                }
            }
            ++braces;
        } else if (t.text == "}") {
            if (--braces <= 0) {
                braces = 0;
                current = {};
            }
        } else if (braces > 0 && !current.empty() && t.kind == GlslToken::Kind::Identifier && i + 1 < tokens.size() &&
                   tokens[i + 1].text == "(") {
            calls[current].insert(t.text);
        }
    }
    // Longest chain by memoised depth-first search over defined functions; -1 marks one in progress.
    std::map<std::string_view, int> depth;
    std::map<std::string_view, std::string_view> deepestCallee;
    std::function<int(std::string_view)> chain = [&](std::string_view name) -> int {
        auto known = depth.find(name);
        if (known != depth.end()) return std::max(known->second, 0);
        auto callee = calls.find(name);
        if (callee == calls.end()) return 0;  // a built-in or a constructor
        depth[name] = -1;
        int deepest = 0;
        for (std::string_view next : callee->second)
            if (const int d = chain(next); d > deepest) deepest = d, deepestCallee[name] = next;
        return depth[name] = deepest + 1;
    };
    DeepestCallChain result;
    for (std::string_view entry : {"mainImage", "mainSound", "mainCubemap"}) {
        auto at = definedAt.find(entry);
        if (at == definedAt.end()) continue;
        const int d = chain(entry) + 1;  // the site's main() calls it
        if (d > result.depth) {
            result.depth = d;
            result.line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<std::ptrdiff_t>(at->second), '\n'));
            // Exact when no function along the chain is overloaded (overloads share one name here).
            result.exact = true;
            for (std::string_view f = entry; !f.empty();) {
                if (definitions[f] > 1) result.exact = false;
                auto next = deepestCallee.find(f);
                f = next == deepestCallee.end() ? std::string_view{} : next->second;
            }
        }
    }
    return result;
}

std::vector<Diagnostic> siteDepthProblems(const ManifestDesc& manifest) {
    std::vector<Diagnostic> problems;
    auto report = [&](bool refused, const std::string& file, const std::string& pass, int line, std::string message) {
        Diagnostic d;
        d.severity = refused ? Severity::Error : Severity::Warning;
        d.code = Code::ShaderCompile;
        d.file = file;
        d.pass = pass;
        d.line = line;
        d.message = std::move(message);
        problems.push_back(std::move(d));
    };
    const std::string limit = std::to_string(kSiteExpressionDepthLimit);
    auto check = [&](std::string_view code, const std::string& file, const std::string& pass) {
        const DeepestStatement atLeast = deepestStatementAtLeast(code);
        if (atLeast.depth > kSiteExpressionDepthLimit) {
            report(true, file, pass, atLeast.line,
                   "an expression nested at least " + std::to_string(atLeast.depth) + " deep: the site refuses this " +
                       "(Chrome rejects expressions deeper than " + limit + ", \"Expression too complex\"; split it " +
                       "with local variables)");
            return;
        }
        const DeepestStatement deepest = deepestStatement(code);
        if (deepest.depth > kSiteExpressionDepthLimit)
            report(false, file, pass, deepest.line,
                   "an expression nested about " + std::to_string(deepest.depth) + " deep: the site may refuse this " +
                       "(Chrome rejects expressions deeper than " + limit + " after folding constants; split it with " +
                       "local variables)");
    };
    if (manifest.commonSource) check(manifest.commonCode, manifest.commonSource->string(), "Common");
    for (const PassDesc& pass : manifest.passes) check(pass.code, pass.sourceName, passName(pass.id));
    // Calls: a pass's functions with Common's, as they are compiled together (Common first, so the
    // pass's line numbers are counted from the pass's own text).
    const std::string common = manifest.commonSource ? manifest.commonCode + "\n" : std::string();
    const int commonLines = static_cast<int>(std::count(common.begin(), common.end(), '\n'));
    auto checkCalls = [&](const PassDesc& pass) {
        const DeepestCallChain deepest = deepestCallChain(common + pass.code);
        if (deepest.depth > kSiteCallDepthLimit)
            report(deepest.exact, pass.sourceName, passName(pass.id), std::max(0, deepest.line - commonLines),
                   "function calls nested " + std::string(deepest.exact ? "" : "about ") + std::to_string(deepest.depth) +
                       " deep: the site " + (deepest.exact ? "refuses" : "may refuse") + " this (Chrome rejects call " +
                       "chains deeper than " + std::to_string(kSiteCallDepthLimit) + ")");
    };
    for (const PassDesc& pass : manifest.passes) checkCalls(pass);
    if (manifest.sound) checkCalls(*manifest.sound);
    return problems;
}

}  // namespace toyhost
