#include "shader/IndexClamp.h"

#include <map>
#include <set>
#include <string_view>
#include <utility>

#include "shader/MacroTable.h"

namespace toyhost {

namespace {

using Kind = GlslToken::Kind;

// What a name or an indexed expression is: `base` a GLSL type name (or a struct's), `array` when
// it is an array of `base` (`size` its literal length, empty when not a literal).
struct Typed {
    std::string_view base;
    bool array = false;
    std::string_view size;
    bool valid() const { return !base.empty(); }
    bool operator==(const Typed&) const = default;
};

// The number of components an index of a non-array `type` selects from (columns of a matrix),
// and what one of them is; 0 for a type that cannot be indexed.
int indexCount(std::string_view type, std::string_view& element) {
    static const std::map<std::string_view, std::pair<int, std::string_view>> types = {
        {"vec2", {2, "float"}},   {"vec3", {3, "float"}},   {"vec4", {4, "float"}},   {"ivec2", {2, "int"}},
        {"ivec3", {3, "int"}},    {"ivec4", {4, "int"}},    {"uvec2", {2, "uint"}},   {"uvec3", {3, "uint"}},
        {"uvec4", {4, "uint"}},   {"bvec2", {2, "bool"}},   {"bvec3", {3, "bool"}},   {"bvec4", {4, "bool"}},
        {"mat2", {2, "vec2"}},    {"mat3", {3, "vec3"}},    {"mat4", {4, "vec4"}},    {"mat2x2", {2, "vec2"}},
        {"mat2x3", {2, "vec3"}},  {"mat2x4", {2, "vec4"}},  {"mat3x2", {3, "vec2"}},  {"mat3x3", {3, "vec3"}},
        {"mat3x4", {3, "vec4"}},  {"mat4x2", {4, "vec2"}},  {"mat4x3", {4, "vec3"}},  {"mat4x4", {4, "vec4"}}};
    const auto found = types.find(type);
    if (found == types.end()) return 0;
    element = found->second.second;
    return found->second.first;
}

bool isBuiltinType(std::string_view w) {
    std::string_view element;
    return w == "float" || w == "int" || w == "uint" || w == "bool" || indexCount(w, element) > 0;
}

bool isQualifier(std::string_view w) {
    static const std::set<std::string_view> words = {"const", "in", "out", "inout", "uniform", "highp", "mediump",
                                                     "lowp", "flat", "smooth", "centroid", "invariant", "precise"};
    return words.count(w) > 0;
}

class Clamper {
public:
    // `hidden`: names never typed (a macro's parameters); `fallback`: the type of a name no scope
    // of these tokens declares (a macro body's names, typed by the text's declarations).
    explicit Clamper(const std::vector<GlslToken>& all, std::set<std::string_view> hidden = {},
                     const std::map<std::string_view, Typed>* fallback = nullptr)
        : hidden_(std::move(hidden)), fallback_(fallback) {
        for (const GlslToken& t : all)
            if (!t.directive) code_.push_back(t);
        scopes_.emplace_back();
        scopes_.back()["iChannelResolution"] = {"vec3", true, "4"};
        scopes_.back()["iChannelTime"] = {"float", true, "4"};
    }

    std::vector<IndexInsertion> run() {
        std::vector<Typed> chain(code_.size());  // what the chain ending at each token is
        struct Open {
            std::size_t at;
            Typed element;
            bool rewrite;
            std::string max;
        };
        std::vector<Open> brackets;
        std::vector<char> parens;  // '(' or '['
        std::set<std::size_t> declarationBrackets;
        std::vector<std::pair<std::string_view, Typed>> pending;  // parameters, until their `{`
        struct DeclList {
            Typed type;
            std::size_t depth = 0;
            bool active = false;
        } list;
        for (std::size_t k = 0; k < code_.size(); ++k) {
            const GlslToken& t = code_[k];
            const std::string_view w = t.text;
            if (t.kind == Kind::Identifier) {
                if (w == "struct" && k + 1 < code_.size() && code_[k + 1].kind == Kind::Identifier)
                    structs_.insert(code_[k + 1].text);
                const bool type = isBuiltinType(w) || structs_.count(w);
                if (type && k + 1 < code_.size() && !(k > 0 && code_[k - 1].text == "struct")) {
                    std::size_t n = k + 1;
                    Typed declared{w, false, {}};
                    if (code_[n].text == "[") {  // `float[4] a`
                        declared.array = true;
                        declared.size = literalSize(n);
                        n = matching(n) + 1;
                    }
                    if (n < code_.size() && code_[n].kind == Kind::Identifier && !isQualifier(code_[n].text) &&
                        !(n + 1 < code_.size() && code_[n + 1].text == "(")) {
                        declare(n, declared, pending, parens.size(), declarationBrackets);
                        list = {declared, parens.size(), true};
                        list.type.size = declared.array ? declared.size : std::string_view{};
                        if (!declared.array) list.type.array = false;
                        k = n;
                        continue;
                    }
                }
                if (!(k > 0 && code_[k - 1].text == ".")) chain[k] = lookup(w);
                continue;
            }
            if (w == "(" || w == "[") {
                if (w == "[" && !declarationBrackets.count(k)) {
                    Open open{k, {}, false, {}};
                    const Typed& left = k > 0 ? chain[k - 1] : Typed{};
                    if (left.valid()) {
                        std::string_view element;
                        if (left.array) {
                            open.element = {left.base, false, {}};
                            open.max = left.size.empty() ? "float(" + std::string(code_[k - 1].text) + ".length()-1)"
                                                         : std::to_string(std::stoi(std::string(left.size)) - 1) + ".0";
                            open.rewrite = left.size.empty() ? code_[k - 1].kind == Kind::Identifier : true;
                        } else if (const int count = indexCount(left.base, element); count > 0) {
                            open.element = {element, false, {}};
                            open.max = std::to_string(count - 1) + ".0";
                            open.rewrite = true;
                        }
                        const std::size_t close = matching(k);
                        if (close >= code_.size() || literalsOnly(k + 1, close)) open.rewrite = false;
                    }
                    brackets.push_back(open);
                } else if (w == "[") {
                    brackets.push_back({k, {}, false, {}});
                }
                parens.push_back(w[0]);
                continue;
            }
            if (w == ")" || w == "]") {
                if (!parens.empty()) parens.pop_back();
                if (list.active && parens.size() < list.depth) list.active = false;
                if (w == "]" && !brackets.empty()) {
                    const Open open = brackets.back();
                    brackets.pop_back();
                    if (open.rewrite) {
                        out_.push_back({code_[open.at + 1].offset, "int(clamp(float("});
                        out_.push_back({t.offset, ")," + std::string("0.0,") + open.max + "))"});
                    }
                    chain[k] = open.element;
                }
                continue;
            }
            if (w == "{") {
                scopes_.emplace_back();
                for (const auto& [name, typed] : pending) scopes_.back()[name] = typed;
                pending.clear();
                list.active = false;
            } else if (w == "}") {
                if (scopes_.size() > 1) scopes_.pop_back();
                list.active = false;
            } else if (w == ";") {
                list.active = false;
                if (parens.empty() && scopes_.size() == 1) pending.clear();
            } else if (w == "," && list.active && parens.size() == list.depth && k + 1 < code_.size() &&
                       code_[k + 1].kind == Kind::Identifier && !isBuiltinType(code_[k + 1].text) &&
                       !isQualifier(code_[k + 1].text) && !structs_.count(code_[k + 1].text)) {
                Typed declared = list.type;
                declare(k + 1, declared, pending, parens.size(), declarationBrackets);
                ++k;
            }
        }
        return out_;
    }

    // The type of each name whose declarations in the text all agree on it (an array whose sizes
    // differ: an array of that type, clamped with `.length()`); a macro body is typed with these,
    // since the browser clamps the expanded text wherever the macro is used.
    std::map<std::string_view, Typed> agreedTypes() const {
        std::map<std::string_view, Typed> agreed;
        for (const auto& [name, types] : declared_) {
            Typed common = types.front();
            for (const Typed& t : types) {
                if (t == common) continue;
                if (!(t.array && common.array && t.base == common.base)) {
                    common = {};
                    break;
                }
                common.size = {};
            }
            if (common.valid()) agreed[name] = common;
        }
        return agreed;
    }

private:
    // The declaration of the name at `n` with `type` (an array when `[` follows it): in the current
    // scope, or, inside a function header's parentheses, for the function's body.
    void declare(std::size_t n, Typed type, std::vector<std::pair<std::string_view, Typed>>& pending,
                 std::size_t depth, std::set<std::size_t>& declarationBrackets) {
        if (n + 1 < code_.size() && code_[n + 1].text == "[") {
            type.array = true;
            type.size = literalSize(n + 1);
            declarationBrackets.insert(n + 1);
        }
        if (depth > 0 && scopes_.size() == 1) pending.emplace_back(code_[n].text, type);
        else scopes_.back()[code_[n].text] = type;
        declared_[code_[n].text].push_back(type);
    }

    Typed lookup(std::string_view name) const {
        if (hidden_.count(name)) return {};
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
            if (const auto found = scope->find(name); found != scope->end()) return found->second;
        if (fallback_)
            if (const auto found = fallback_->find(name); found != fallback_->end()) return found->second;
        return {};
    }

    // The index of the `]` matching the `[` at `k` (code_.size() when unmatched).
    std::size_t matching(std::size_t k) const {
        int depth = 0;
        for (; k < code_.size(); ++k) {
            if (code_[k].text == "[" || code_[k].text == "(") ++depth;
            else if ((code_[k].text == "]" || code_[k].text == ")") && --depth == 0) return k;
        }
        return code_.size();
    }

    // The literal between `[` at `k` and its `]`, when that is all there is.
    std::string_view literalSize(std::size_t k) const {
        if (k + 2 < code_.size() && code_[k + 1].kind == Kind::Number && code_[k + 2].text == "]") {
            const std::string_view s = code_[k + 1].text;
            if (s.find_first_not_of("0123456789") == std::string_view::npos && s.size() < 9 && s != "0") return s;
        }
        return {};
    }

    bool literalsOnly(std::size_t from, std::size_t to) const {
        for (std::size_t k = from; k < to; ++k)
            if (code_[k].kind == Kind::Identifier) return false;
        return true;
    }

    std::vector<GlslToken> code_;
    std::vector<std::map<std::string_view, Typed>> scopes_;
    std::set<std::string_view> structs_;
    std::vector<IndexInsertion> out_;
    std::map<std::string_view, std::vector<Typed>> declared_;
    std::set<std::string_view> hidden_;
    const std::map<std::string_view, Typed>* fallback_ = nullptr;
};

}  // namespace

std::vector<IndexInsertion> clampDynamicIndices(const std::vector<GlslToken>& tokens) {
    Clamper code(tokens);
    std::vector<IndexInsertion> out = code.run();
    const MacroTable macros(tokens);
    if (macros.empty()) return out;
    // ANGLE clamps the text after preprocessing: an index written in a macro body is clamped at
    // every use, so it is clamped in the body (a parameter is an index like any other).
    const std::map<std::string_view, Typed> agreed = code.agreedTypes();
    for (const auto& [name, macro] : macros.all()) {
        if (macro.body.empty()) continue;
        Clamper body(macro.body, {macro.parameters.begin(), macro.parameters.end()}, &agreed);
        for (IndexInsertion& insertion : body.run()) out.push_back(std::move(insertion));
    }
    return out;
}

}  // namespace toyhost
