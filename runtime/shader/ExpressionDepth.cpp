#include "shader/ExpressionDepth.h"

#include <algorithm>
#include <array>
#include <functional>
#include <map>
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

DeepestCallChain deepestCallChain(std::string_view code) {
    const std::vector<GlslToken> tokens = tokenizeGlsl(code);
    // Top-level function definitions: `type name ( ... ) {` at brace depth 0; the calls in each body.
    std::map<std::string_view, std::set<std::string_view>> calls;
    std::map<std::string_view, std::size_t> definedAt;  // offset of the name
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
    std::function<int(std::string_view)> chain = [&](std::string_view name) -> int {
        auto known = depth.find(name);
        if (known != depth.end()) return std::max(known->second, 0);
        auto callee = calls.find(name);
        if (callee == calls.end()) return 0;  // a built-in or a constructor
        depth[name] = -1;
        int deepest = 0;
        for (std::string_view next : callee->second) deepest = std::max(deepest, chain(next));
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
        }
    }
    return result;
}

std::vector<Diagnostic> deepExpressionWarnings(const ManifestDesc& manifest) {
    std::vector<Diagnostic> warnings;
    auto warn = [&](const std::string& file, const std::string& pass, int line, std::string message) {
        Diagnostic d;
        d.severity = Severity::Warning;
        d.code = Code::ShaderCompile;
        d.file = file;
        d.pass = pass;
        d.line = line;
        d.message = std::move(message);
        warnings.push_back(std::move(d));
    };
    auto check = [&](std::string_view code, const std::string& file, const std::string& pass) {
        const DeepestStatement deepest = deepestStatement(code);
        if (deepest.depth > kSiteExpressionDepthLimit)
            warn(file, pass, deepest.line,
                 "an expression nested about " + std::to_string(deepest.depth) + " deep: the site refuses this " +
                     "(Chrome rejects expressions deeper than " + std::to_string(kSiteExpressionDepthLimit) +
                     "; split it with local variables)");
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
            warn(pass.sourceName, passName(pass.id), std::max(0, deepest.line - commonLines),
                 "function calls nested about " + std::to_string(deepest.depth) + " deep: the site refuses this " +
                     "(Chrome rejects call chains deeper than " + std::to_string(kSiteCallDepthLimit) + ")");
    };
    for (const PassDesc& pass : manifest.passes) checkCalls(pass);
    if (manifest.sound) checkCalls(*manifest.sound);
    return warnings;
}

}  // namespace toyhost
