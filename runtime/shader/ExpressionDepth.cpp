#include "shader/ExpressionDepth.h"

#include <algorithm>
#include <array>
#include <map>
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

std::vector<Diagnostic> deepExpressionWarnings(const ManifestDesc& manifest) {
    std::vector<Diagnostic> warnings;
    auto check = [&](std::string_view code, const std::string& file, const std::string& pass) {
        const DeepestStatement deepest = deepestStatement(code);
        if (deepest.depth <= kSiteExpressionDepthLimit) return;
        Diagnostic d;
        d.severity = Severity::Warning;
        d.code = Code::ShaderCompile;
        d.file = file;
        d.pass = pass;
        d.line = deepest.line;
        d.message = "an expression nested about " + std::to_string(deepest.depth) + " deep: the site refuses this " +
                    "(Chrome rejects expressions deeper than " + std::to_string(kSiteExpressionDepthLimit) +
                    "; split it with local variables)";
        warnings.push_back(std::move(d));
    };
    if (manifest.commonSource) check(manifest.commonCode, manifest.commonSource->string(), "Common");
    for (const PassDesc& pass : manifest.passes) check(pass.code, pass.sourceName, passName(pass.id));
    return warnings;
}

}  // namespace toyhost
