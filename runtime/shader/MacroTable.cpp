#include "shader/MacroTable.h"

#include <set>

namespace toyhost {

namespace {

bool sameBody(const Macro& a, const Macro& b) {
    if (a.functionLike != b.functionLike || a.parameters != b.parameters || a.body.size() != b.body.size()) return false;
    for (std::size_t i = 0; i < a.body.size(); ++i)
        if (a.body[i].text != b.body[i].text) return false;
    return true;
}

}  // namespace

MacroTable::MacroTable(const std::vector<GlslToken>& tokens) {
    std::set<std::string_view> dropped;
    for (std::size_t i = 0; i + 2 < tokens.size(); ++i) {
        if (!tokens[i].directiveStart) continue;
        const std::string_view word = tokens[i + 1].text;
        const GlslToken& name = tokens[i + 2];
        if (tokens[i + 1].directiveStart || name.directiveStart || !name.directive || name.kind != GlslToken::Kind::Identifier)
            continue;
        if (word == "undef") {
            dropped.insert(name.text);
            continue;
        }
        if (word != "define") continue;
        Macro macro;
        std::size_t k = i + 3;
        auto inLine = [&](std::size_t j) { return j < tokens.size() && tokens[j].directive && !tokens[j].directiveStart; };
        // A function-like macro's `(` follows its name directly.
        if (inLine(k) && tokens[k].text == "(" && tokens[k].offset == name.offset + name.text.size()) {
            macro.functionLike = true;
            ++k;
            bool closed = false;
            while (inLine(k)) {
                const std::string_view t = tokens[k++].text;
                if (t == ")") {
                    closed = true;
                    break;
                }
                if (t != ",") macro.parameters.push_back(t);
            }
            if (!closed) continue;
        }
        macro.bodyFirst = k;
        for (; inLine(k); ++k) {
            GlslToken copy = tokens[k];
            copy.directive = false;
            macro.body.push_back(copy);
        }
        const auto [at, added] = macros_.emplace(name.text, macro);
        if (!added && !sameBody(at->second, macro)) dropped.insert(name.text);
    }
    for (std::string_view name : dropped) macros_.erase(name);
}

const Macro* MacroTable::find(std::string_view name) const {
    const auto found = macros_.find(name);
    return found == macros_.end() ? nullptr : &found->second;
}

std::optional<MacroTable::Expansion> MacroTable::expand(const Macro& macro, const std::vector<GlslToken>& tokens, std::size_t at) {
    Expansion out;
    out.end = at + 1;
    if (!macro.functionLike) {
        out.tokens = macro.body;
        return out;
    }
    if (out.end >= tokens.size() || tokens[out.end].text != "(") return std::nullopt;
    std::vector<std::vector<GlslToken>> arguments(1);
    int depth = 0;
    std::size_t k = out.end + 1;
    for (; k < tokens.size(); ++k) {
        const std::string_view t = tokens[k].text;
        if (tokens[k].directive != tokens[at].directive) return std::nullopt;
        if (t == "(" || t == "[") ++depth;
        else if ((t == ")" || t == "]") && depth > 0) --depth;
        else if (t == ")") break;
        if (t == "," && depth == 0) arguments.emplace_back();
        else arguments.back().push_back(tokens[k]);
    }
    if (k >= tokens.size()) return std::nullopt;
    out.end = k + 1;
    if (macro.parameters.empty() && arguments.size() == 1 && arguments[0].empty()) arguments.clear();
    if (arguments.size() != macro.parameters.size()) return std::nullopt;
    for (const GlslToken& t : macro.body) {
        std::size_t p = 0;
        while (p < macro.parameters.size() && macro.parameters[p] != t.text) ++p;
        if (t.kind == GlslToken::Kind::Identifier && p < macro.parameters.size())
            out.tokens.insert(out.tokens.end(), arguments[p].begin(), arguments[p].end());
        else
            out.tokens.push_back(t);
    }
    return out;
}

}  // namespace toyhost
