#include "shader/FloatConstantFold.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "shader/MacroTable.h"

namespace toyhost {
namespace {

using Kind = GlslToken::Kind;

// A float scalar (`size` 1) or vector; `integer` for an int literal, which only a constructor
// (`float(5)`) may take.
struct Value {
    int size = 1;
    std::array<float, 4> c{};
    bool integer = false;
};

// One component of a built-in: its value and whether ANGLE chose it (the arguments are undefined
// for GLSL, or round() meets a half).
struct Component {
    float value = 0.0f;
    bool decided = false;
};

Component undefinedComponent() { return {0.0f, true}; }

int swizzleIndex(char c) {
    for (const char* set : {"xyzw", "rgba", "stpq"})
        for (int i = 0; i < 4; ++i)
            if (set[i] == c) return i;
    return -1;
}

int floatVectorSize(std::string_view type) {
    if (type == "float") return 1;
    if (type.size() == 4 && type.substr(0, 3) == "vec" && type[3] >= '2' && type[3] <= '4') return type[3] - '0';
    return 0;
}

// ANGLE's folding of the float built-ins, one component at a time (shader/FloatConstantFold.h).
std::optional<Component> unaryBuiltin(std::string_view f, float x) {
    if (f == "log") return x <= 0.0f ? undefinedComponent() : Component{std::log(x)};
    if (f == "log2") return x <= 0.0f ? undefinedComponent() : Component{std::log(x) / std::log(2.0f)};
    if (f == "sqrt") return x < 0.0f ? undefinedComponent() : Component{std::sqrt(x)};
    if (f == "inversesqrt") return x <= 0.0f ? undefinedComponent() : Component{1.0f / std::sqrt(x)};
    if (f == "acosh") return x < 1.0f ? undefinedComponent() : Component{std::acosh(x)};
    if (f == "atanh") return std::fabs(x) >= 1.0f ? undefinedComponent() : Component{std::atanh(x)};
    if (f == "round") {
        // Half away from zero (C's roundf); Mesa folds half to even.
        const float away = std::round(x);
        return Component{away, away != std::nearbyint(x) || std::signbit(away) != std::signbit(std::nearbyint(x))};
    }
    if (f == "sin") return Component{std::sin(x)};
    if (f == "cos") return Component{std::cos(x)};
    if (f == "tan") return Component{std::tan(x)};
    if (f == "exp") return Component{std::exp(x)};
    if (f == "exp2") return Component{std::exp2(x)};
    if (f == "abs") return Component{std::fabs(x)};
    if (f == "floor") return Component{std::floor(x)};
    if (f == "ceil") return Component{std::ceil(x)};
    if (f == "trunc") return Component{std::trunc(x)};
    if (f == "fract") return Component{x - std::floor(x)};
    if (f == "sign") return Component{x > 0.0f ? 1.0f : x < 0.0f ? -1.0f : 0.0f};
    if (f == "atan") return Component{std::atan(x)};
    return std::nullopt;
}

std::optional<Component> binaryBuiltin(std::string_view f, float x, float y) {
    if (f == "pow") return x < 0.0f || (x == 0.0f && y <= 0.0f) ? undefinedComponent() : Component{std::pow(x, y)};
    if (f == "atan") return x == 0.0f && y == 0.0f ? undefinedComponent() : Component{std::atan2(x, y)};  // atan(y, x)
    if (f == "min") return Component{std::min(x, y)};
    if (f == "max") return Component{std::max(x, y)};
    if (f == "mod") return Component{x - y * std::floor(x / y)};
    return std::nullopt;
}

std::optional<Component> ternaryBuiltin(std::string_view f, float a, float b, float x) {
    if (f == "smoothstep") {
        if (a >= b) return undefinedComponent();
        const float t = std::clamp((x - a) / (b - a), 0.0f, 1.0f);
        return Component{t * t * (3.0f - 2.0f * t)};
    }
    if (f == "clamp") return b > x ? undefinedComponent() : Component{std::clamp(a, b, x)};  // clamp(a, min b, max x)
    if (f == "mix") return Component{a * (1.0f - x) + b * x};
    return std::nullopt;
}

bool isBuiltin(std::string_view f) {
    static const std::set<std::string_view> names = {
        "log",  "log2", "sqrt", "inversesqrt", "acosh", "atanh", "round", "sin",   "cos",   "tan",       "exp",
        "exp2", "abs",  "floor", "ceil",       "trunc", "fract", "sign",  "atan",  "pow",   "min",       "max",
        "mod",  "smoothstep", "clamp", "mix",  "normalize", "length", "dot"};
    return names.count(f) > 0;
}

struct Shared {
    const MacroTable& macros;
    std::map<std::string_view, Value> constants;
    std::set<std::string_view> expanding;  // macros being read (a macro naming itself)
    std::size_t steps = 0;
    std::size_t stepBudget = 0;
    int nesting = 0;
};

// Evaluates constant float expressions of one run of tokens: code (`directive` false) or one
// directive line's (a macro body; then `hidden` names its parameters, never constants).
class Evaluator {
public:
    Evaluator(const std::vector<GlslToken>& tokens, Shared& shared, bool directive, const std::set<std::string_view>* hidden)
        : t_(tokens), shared_(shared), directive_(directive), hidden_(hidden) {}

    // The built-in call whose name is at `at`: its value and whether ANGLE chose any component;
    // `at` moves past its `)`.
    std::optional<std::pair<Value, bool>> call(std::size_t& at) {
        const std::string_view f = t_[at].text;
        if (!isBuiltin(f) || !has(at + 1) || t_[at + 1].text != "(") return std::nullopt;
        at += 2;
        std::vector<Value> args;
        while (true) {
            std::optional<Value> v = parse(at, 1);
            if (!v || v->integer || !has(at)) return std::nullopt;
            args.push_back(*v);
            if (t_[at].text == ")") break;
            if (t_[at].text != ",") return std::nullopt;
            ++at;
        }
        ++at;
        int size = 1;
        for (const Value& a : args) size = std::max(size, a.size);
        for (const Value& a : args)
            if (a.size != 1 && a.size != size) return std::nullopt;
        Value out;
        out.size = size;
        bool decided = false;
        auto component = [](const Value& v, int i) { return v.c[static_cast<std::size_t>(v.size == 1 ? 0 : i)]; };
        if (f == "normalize" || f == "length" || f == "dot") {
            if ((f == "dot") != (args.size() == 2) || (f != "dot" && args.size() != 1)) return std::nullopt;
            float sum = 0.0f;
            for (int i = 0; i < size; ++i) sum += component(args[0], i) * component(args.back(), i);
            const float length = std::sqrt(sum);
            if (f != "normalize") {
                out.size = 1;
                out.c[0] = f == "dot" ? sum : length;
                return std::make_pair(out, false);
            }
            for (int i = 0; i < size; ++i) out.c[static_cast<std::size_t>(i)] = length != 0.0f ? component(args[0], i) / length : 0.0f;
            return std::make_pair(out, length == 0.0f);
        }
        for (int i = 0; i < size; ++i) {
            std::optional<Component> one;
            if (args.size() == 1) one = unaryBuiltin(f, component(args[0], i));
            else if (args.size() == 2) one = binaryBuiltin(f, component(args[0], i), component(args[1], i));
            else if (args.size() == 3) one = ternaryBuiltin(f, component(args[0], i), component(args[1], i), component(args[2], i));
            if (!one) return std::nullopt;
            out.c[static_cast<std::size_t>(i)] = one->value;
            decided = decided || one->decided;
        }
        return std::make_pair(out, decided);
    }

    // The expression at `at` made of operators binding at least `minP`; `at` moves past it.
    std::optional<Value> parse(std::size_t& at, int minP) {
        std::optional<Value> left = unary(at);
        while (left && has(at) && t_[at].kind == Kind::Punct) {
            const std::string_view op = t_[at].text;
            const int p = glslBinaryStrength(op);
            if (p == 0 || p < minP) break;
            if (op != "+" && op != "-" && op != "*" && op != "/") return std::nullopt;
            ++at;
            const std::optional<Value> right = parse(at, p + 1);
            if (!right || left->integer || right->integer) return std::nullopt;
            if (left->size != 1 && right->size != 1 && left->size != right->size) return std::nullopt;
            Value out;
            out.size = std::max(left->size, right->size);
            for (std::size_t i = 0; i < static_cast<std::size_t>(out.size); ++i) {
                const float a = left->c[left->size == 1 ? 0 : i];
                const float b = right->c[right->size == 1 ? 0 : i];
                out.c[i] = op == "+" ? a + b : op == "-" ? a - b : op == "*" ? a * b : a / b;
            }
            left = out;
        }
        if (left && has(at)) {
            const std::string_view next = t_[at].text;
            if (next == "." || next == "[" || next == "(" || next == "++" || next == "--") return std::nullopt;
        }
        return left;
    }

    // True when `at` is inside this run of tokens.
    bool has(std::size_t at) const {
        return at < t_.size() && t_[at].directive == directive_ && !t_[at].directiveStart;
    }

private:
    std::optional<Value> unary(std::size_t& at) {
        if (!has(at)) return std::nullopt;
        if (shared_.nesting > kMostNesting || ++shared_.steps > shared_.stepBudget) return std::nullopt;
        struct Nested {
            int& n;
            explicit Nested(int& level) : n(++level) {}
            ~Nested() { --n; }
        } nested(shared_.nesting);
        const std::string_view t = t_[at].text;
        if (t == "-" || t == "+") {
            ++at;
            std::optional<Value> v = unary(at);
            if (v && t == "-")
                for (float& c : v->c) c = -c;
            return v;
        }
        std::optional<Value> v = primary(at);
        while (v && v->size > 1 && has(at + 1)) {
            if (t_[at].text == "." && t_[at + 1].kind == Kind::Identifier && t_[at + 1].text.size() <= 4) {
                Value picked = *v;
                picked.size = static_cast<int>(t_[at + 1].text.size());
                for (std::size_t i = 0; i < t_[at + 1].text.size(); ++i) {
                    const int from = swizzleIndex(t_[at + 1].text[i]);
                    if (from < 0 || from >= v->size) return std::nullopt;
                    picked.c[i] = v->c[static_cast<std::size_t>(from)];
                }
                v = picked;
                at += 2;
            } else if (t_[at].text == "[" && has(at + 2) && t_[at + 2].text == "]" && t_[at + 1].text.size() == 1 &&
                       t_[at + 1].text[0] >= '0' && t_[at + 1].text[0] < '0' + v->size) {
                v->c[0] = v->c[static_cast<std::size_t>(t_[at + 1].text[0] - '0')];
                v->size = 1;
                at += 3;
            } else {
                break;
            }
        }
        return v;
    }

    std::optional<Value> primary(std::size_t& at) {
        const GlslToken& t = t_[at];
        if (t.kind == Kind::Number) {
            ++at;
            return literal(t.text);
        }
        if (t.text == "(") {
            ++at;
            std::optional<Value> v = parse(at, 1);
            if (!v || !has(at) || t_[at].text != ")") return std::nullopt;
            ++at;
            return v;
        }
        if (t.kind != Kind::Identifier || (hidden_ && hidden_->count(t.text))) return std::nullopt;
        if (const int size = floatVectorSize(t.text); size > 0) return constructor(at, size);
        if (isBuiltin(t.text)) {
            std::optional<std::pair<Value, bool>> called = call(at);
            if (!called) return std::nullopt;
            return called->first;
        }
        if (const auto found = shared_.constants.find(t.text); found != shared_.constants.end()) {
            ++at;
            return found->second;
        }
        // An object-like macro whose body is one operand: the browser folds the expanded text.
        const Macro* macro = shared_.macros.find(t.text);
        if (!macro || macro->functionLike || macro->body.empty() || shared_.expanding.count(t.text)) return std::nullopt;
        shared_.expanding.insert(t.text);
        Evaluator body(macro->body, shared_, false, nullptr);
        std::size_t bodyAt = 0;
        std::optional<Value> v = body.unary(bodyAt);
        shared_.expanding.erase(t.text);
        if (!v || bodyAt != macro->body.size()) return std::nullopt;
        ++at;
        return v;
    }

    // `float(...)` or `vecN(...)`: every argument's components in turn, or one scalar for all.
    std::optional<Value> constructor(std::size_t& at, int size) {
        if (!has(at + 1) || t_[at + 1].text != "(") return std::nullopt;
        at += 2;
        Value made;
        made.size = size;
        int filled = 0;
        bool broadcast = false;
        for (int argument = 0;; ++argument) {
            const std::optional<Value> v = parse(at, 1);
            if (!v || !has(at)) return std::nullopt;
            if (argument == 0 && v->size == 1 && t_[at].text == ")") broadcast = true;
            for (int i = 0; i < v->size && filled < size; ++i)
                made.c[static_cast<std::size_t>(filled++)] = v->c[static_cast<std::size_t>(i)];
            if (t_[at].text == ")") break;
            if (t_[at].text != ",") return std::nullopt;
            ++at;
        }
        ++at;
        if (broadcast) made.c.fill(made.c[0]);
        else if (filled < size) return std::nullopt;
        return made;
    }

    // A float literal (`1.`, `.5e-3`, `2.0f`), or a decimal int literal for a constructor.
    static std::optional<Value> literal(std::string_view text) {
        std::string s(text);
        Value v;
        if (s.find_first_of("xXuU") != std::string::npos) return std::nullopt;
        if (s.find_first_of(".eE") == std::string::npos) {
            if (s.size() > 1 && s[0] == '0') return std::nullopt;  // octal: left alone
            v.integer = true;
        } else if (s.back() == 'f' || s.back() == 'F') {
            s.pop_back();
        }
        char* end = nullptr;
        v.c[0] = std::strtof(s.c_str(), &end);
        if (end != s.c_str() + s.size()) return std::nullopt;
        return v;
    }

    static constexpr int kMostNesting = 512;
    const std::vector<GlslToken>& t_;
    Shared& shared_;
    bool directive_;
    const std::set<std::string_view>* hidden_;
};

std::string floatText(float x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(x));
    std::string out = buffer;
    if (out.find_first_of(".e") == std::string::npos) out += ".0";
    return std::signbit(x) ? "(" + out + ")" : out;
}

// The value as GLSL text, or empty when a component is not finite.
std::string valueText(const Value& v) {
    std::string out;
    for (std::size_t i = 0; i < static_cast<std::size_t>(v.size); ++i) {
        if (!std::isfinite(v.c[i])) return {};
        out += (i ? ", " : "") + floatText(v.c[i]);
    }
    return v.size == 1 ? out : "vec" + std::to_string(v.size) + "(" + out + ")";
}

// The parameters of the function-like macro a `#define` at `hash` (the `#`) defines, and the index
// of its body's first token.
std::pair<std::set<std::string_view>, std::size_t> defineParameters(const std::vector<GlslToken>& t, std::size_t hash) {
    std::set<std::string_view> parameters;
    std::size_t k = hash + 3;
    if (k < t.size() && t[k].directive && !t[k].directiveStart && t[k].text == "(" &&
        t[k].offset == t[hash + 2].offset + t[hash + 2].text.size()) {
        for (++k; k < t.size() && t[k].directive && !t[k].directiveStart && t[k].text != ")"; ++k)
            if (t[k].text != ",") parameters.insert(t[k].text);
        ++k;
    }
    return {parameters, k};
}

class Folder {
public:
    explicit Folder(const std::vector<GlslToken>& tokens) : t_(tokens), macros_(tokens), shared_{macros_, {}, {}, 0, 0, 0} {
        shared_.stepBudget = 64 * tokens.size() + 100000;
    }

    std::vector<ConstantFoldEdit> run() {
        collectConstants();
        std::vector<ConstantFoldEdit> edits;
        std::size_t hash = 0;  // the `#` of the current directive line
        std::set<std::string_view> parameters;
        std::size_t bodyFirst = 0;
        bool define = false;
        for (std::size_t i = 0; i < t_.size(); ++i) {
            const GlslToken& t = t_[i];
            if (t.directiveStart) {
                hash = i;
                define = i + 2 < t_.size() && t_[i + 1].text == "define" && t_[i + 2].directive && !t_[i + 2].directiveStart;
                if (define) std::tie(parameters, bodyFirst) = defineParameters(t_, hash);
                continue;
            }
            if (t.kind != Kind::Identifier || i + 1 >= t_.size() || t_[i + 1].text != "(") continue;
            if (i > 0 && t_[i - 1].text == ".") continue;
            if (t.directive && (!define || i < bodyFirst)) continue;
            if (isBuiltin(t.text)) {
                Evaluator evaluator(t_, shared_, t.directive, t.directive ? &parameters : nullptr);
                std::size_t at = i;
                const std::optional<std::pair<Value, bool>> called = evaluator.call(at);
                if (called && called->second) add(edits, i, at, called->first);
            } else if (const Macro* macro = macros_.find(t.text); macro && macro->functionLike && !t.directive) {
                invocation(edits, i, *macro);
            }
        }
        return outermostEdits(std::move(edits));
    }

private:
    // `const [precision] float|vecN NAME = expr (, NAME = expr)* ;` read once each; a name declared
    // in another way too is not used (it may be shadowed).
    void collectConstants() {
        std::map<std::string_view, int> declarations = countDeclarations(t_);
        std::set<std::string_view> ambiguous;
        for (std::size_t i = 0; i + 4 < t_.size(); ++i) {
            if (t_[i].directive || t_[i].text != "const") continue;
            std::size_t j = i + 1;
            if (t_[j].text == "highp" || t_[j].text == "mediump" || t_[j].text == "lowp") ++j;
            const int size = j < t_.size() ? floatVectorSize(t_[j].text) : 0;
            if (size == 0) continue;
            ++j;
            while (j + 2 < t_.size() && t_[j].kind == Kind::Identifier && t_[j + 1].text == "=") {
                const std::string_view name = t_[j].text;
                std::size_t at = j + 2;
                Evaluator evaluator(t_, shared_, false, nullptr);
                const std::optional<Value> v = evaluator.parse(at, 1);
                if (v && !v->integer && v->size == size && declarations[name] <= 1 && !shared_.constants.count(name))
                    shared_.constants[name] = *v;
                else
                    ambiguous.insert(name);
                while (at < t_.size() && t_[at].text != "," && t_[at].text != ";") ++at;
                if (at >= t_.size() || t_[at].text == ";") break;
                j = at + 1;
            }
        }
        for (std::string_view name : ambiguous) shared_.constants.erase(name);
    }

    // A function-like macro invoked at `i` whose expansion is one built-in call (in parentheses or
    // not) that ANGLE decides: the invocation is replaced by the call's value.
    void invocation(std::vector<ConstantFoldEdit>& edits, std::size_t i, const Macro& macro) {
        const std::optional<MacroTable::Expansion> expansion = MacroTable::expand(macro, t_, i);
        if (!expansion || expansion->tokens.empty()) return;
        const std::vector<GlslToken>& e = expansion->tokens;
        std::size_t first = 0;
        std::size_t last = e.size();
        while (first < last && e[first].text == "(" && e[last - 1].text == ")") ++first, --last;
        if (first >= last || !isBuiltin(e[first].text)) return;
        Evaluator evaluator(e, shared_, false, nullptr);
        std::size_t at = first;
        const std::optional<std::pair<Value, bool>> called = evaluator.call(at);
        if (called && called->second && at == last) add(edits, i, expansion->end, called->first);
    }

    // An edit writing `v` in place of tokens [first, past), keeping the span's newlines after it
    // (none in a directive, where they would end the line: such a span is left alone).
    void add(std::vector<ConstantFoldEdit>& edits, std::size_t first, std::size_t past, const Value& v) const {
        std::string text = valueText(v);
        if (text.empty()) return;
        const char* begin = t_[first].text.data();
        const char* stop = t_[past - 1].text.data() + t_[past - 1].text.size();
        const std::string_view span(begin, static_cast<std::size_t>(stop - begin));
        const auto newlines = static_cast<std::size_t>(std::count(span.begin(), span.end(), '\n'));
        if (newlines > 0 && t_[first].directive) return;
        ConstantFoldEdit edit;
        edit.offset = t_[first].offset;
        edit.erase = span.size();
        edit.text = std::move(text);
        edit.text.append(newlines, '\n');
        edits.push_back(std::move(edit));
    }

    const std::vector<GlslToken>& t_;
    MacroTable macros_;
    Shared shared_;
};

}  // namespace

std::vector<ConstantFoldEdit> foldAngleFloatBuiltins(const std::vector<GlslToken>& tokens) { return Folder(tokens).run(); }

}  // namespace toyhost
