#include "shader/IntegerConstantFold.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

#include "shader/MacroTable.h"

namespace toyhost {
namespace {

using Kind = GlslToken::Kind;

// An int or uint scalar (`size` 1) or vector (2 to 4 components).
struct Value {
    bool isUint = false;
    int size = 1;
    std::array<std::uint32_t, 4> bits{};
    std::int32_t asInt(int c = 0) const { return static_cast<std::int32_t>(bits[static_cast<std::size_t>(c)]); }
};

// The component index of a swizzle letter (xyzw, rgba, stpq); -1 for any other character.
int swizzleIndex(char c) {
    for (const char* set : {"xyzw", "rgba", "stpq"})
        for (int i = 0; i < 4; ++i)
            if (set[i] == c) return i;
    return -1;
}

bool isKeyword(std::string_view word) {
    static const std::set<std::string_view> kKeywords = {"return", "case", "else", "do", "if", "while", "for",
                                                         "switch", "break", "continue", "discard", "default"};
    return kKeywords.count(word) != 0;
}

// An integer literal as GLSL ES 3.00 reads it: decimal, octal (leading 0) or hex, `u` for uint.
// Decimal literals past INT_MAX without `u`, floats and anything malformed are not read.
std::optional<Value> readLiteral(std::string_view text) {
    Value v;
    if (!text.empty() && (text.back() == 'u' || text.back() == 'U')) {
        v.isUint = true;
        text.remove_suffix(1);
    }
    if (text.empty()) return std::nullopt;
    int base = 10;
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        text.remove_prefix(2);
    } else if (text.size() > 1 && text[0] == '0') {
        base = 8;
        text.remove_prefix(1);
    }
    std::uint64_t n = 0;
    for (char c : text) {
        int digit = -1;
        if (c >= '0' && c <= '9') digit = c - '0';
        else if (base == 16 && c >= 'a' && c <= 'f') digit = c - 'a' + 10;
        else if (base == 16 && c >= 'A' && c <= 'F') digit = c - 'A' + 10;
        if (digit < 0 || digit >= base) return std::nullopt;
        n = n * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(digit);
        if (n > 0xFFFFFFFFull) return std::nullopt;
    }
    if (base == 10 && !v.isUint && n > 0x7FFFFFFFull) return std::nullopt;
    v.bits[0] = static_cast<std::uint32_t>(n);
    return v;
}

// What ANGLE's folder gives for `a op b` on one component, and whether that value is its own
// choice (an operation GLSL ES leaves undefined). nullopt for an operator it does not fold.
struct Component {
    std::uint32_t bits = 0;
    bool undefinedInGlsl = false;
};

std::optional<Component> foldComponent(std::string_view op, bool isUint, std::uint32_t a, bool rightUint, std::uint32_t b) {
    constexpr std::int32_t kIntMin = std::numeric_limits<std::int32_t>::min();
    constexpr std::int32_t kIntMax = std::numeric_limits<std::int32_t>::max();
    const auto ai = static_cast<std::int32_t>(a);
    const auto bi = static_cast<std::int32_t>(b);
    Component out;
    if (op == "<<" || op == ">>") {
        const bool valid = rightUint ? b <= 31u : (bi >= 0 && bi <= 31);
        if (!valid) out.undefinedInGlsl = true;
        else if (op == "<<") out.bits = a << b;
        else if (isUint || ai >= 0) out.bits = a >> b;
        else out.bits = ~(~a >> b);  // the sign extends
        return out;
    }
    if (op == "/" || op == "%") {
        if (b == 0) {
            out.undefinedInGlsl = true;
            out.bits = isUint ? 0xFFFFFFFFu : static_cast<std::uint32_t>(kIntMax);
        } else if (isUint) {
            out.bits = op == "/" ? a / b : a % b;
        } else if (op == "/") {
            if (ai == kIntMin && bi == -1) {
                out.undefinedInGlsl = true;
                out.bits = static_cast<std::uint32_t>(kIntMax);
            } else {
                out.bits = static_cast<std::uint32_t>(ai / bi);
            }
        } else if (ai < 0 || bi < 0) {
            out.undefinedInGlsl = true;
        } else {
            out.bits = static_cast<std::uint32_t>(ai % bi);
        }
        return out;
    }
    // The rest wrap in 32 bits, for int as for uint.
    if (op == "*") out.bits = a * b;
    else if (op == "+") out.bits = a + b;
    else if (op == "-") out.bits = a - b;
    else if (op == "&") out.bits = a & b;
    else if (op == "^") out.bits = a ^ b;
    else if (op == "|") out.bits = a | b;
    else return std::nullopt;
    return out;
}

// `a op b` component by component (a scalar operand applies to every component of the other, as
// ANGLE folds `ivec2(7) / 0`), and whether any component is ANGLE's own choice. nullopt for
// operand types GLSL refuses together.
struct Folded {
    Value value;
    bool undefinedInGlsl = false;
};

std::optional<Folded> fold(std::string_view op, const Value& a, const Value& b) {
    const bool shift = op == "<<" || op == ">>";
    if (shift ? (a.size == 1 && b.size > 1) : a.isUint != b.isUint) return std::nullopt;
    if (a.size > 1 && b.size > 1 && a.size != b.size) return std::nullopt;
    Folded out;
    out.value.isUint = a.isUint;
    out.value.size = std::max(a.size, b.size);
    for (int c = 0; c < out.value.size; ++c) {
        const std::optional<Component> one =
            foldComponent(op, a.isUint, a.bits[static_cast<std::size_t>(a.size == 1 ? 0 : c)], b.isUint,
                          b.bits[static_cast<std::size_t>(b.size == 1 ? 0 : c)]);
        if (!one) return std::nullopt;
        out.value.bits[static_cast<std::size_t>(c)] = one->bits;
        out.undefinedInGlsl = out.undefinedInGlsl || one->undefinedInGlsl;
    }
    return out;
}

// The components of `ivecN` / `uvecN` (`vectorSize` N) for a type name; 0 for any other word.
int integerVectorSize(std::string_view type, bool& isUint) {
    if (type.size() != 5 || type.substr(1, 3) != "vec" || type[4] < '2' || type[4] > '4') return 0;
    if (type[0] != 'i' && type[0] != 'u') return 0;
    isUint = type[0] == 'u';
    return type[4] - '0';
}

bool endsOperand(const GlslToken& t) {
    if (t.kind == Kind::Number) return true;
    if (t.kind == Kind::Identifier) return !isKeyword(t.text);
    return t.text == ")" || t.text == "]";
}

class Folder {
public:
    explicit Folder(const std::vector<GlslToken>& tokens) : t_(tokens), macros_(tokens) {}

    std::vector<ConstantFoldEdit> run() {
        collectConstants();
        std::vector<ConstantFoldEdit> edits;
        for (std::size_t i = 0; i < t_.size(); ++i) {
            const GlslToken& op = t_[i];
            if (op.directive || op.kind != Kind::Punct) continue;
            const int p = glslBinaryStrength(op.text);
            if (p != kGlslMultiplicative && p != kGlslShift) continue;
            if (op.text == "*") continue;
            if (i + 1 < t_.size() && t_[i + 1].text == "=" && t_[i + 1].offset == op.offset + op.text.size())
                continue;  // `<<=`, `>>=`: an assignment, never constant
            const std::optional<std::size_t> start = leftOperandStart(i, p);
            if (!start || (*start > 0 && t_[*start - 1].text == ".")) continue;  // `s.N / 0`: a member
            std::size_t at = *start;
            const std::optional<Value> left = parse(at, i, p);
            if (!left || at != i) continue;
            at = i + 1;
            const std::optional<Value> right = parse(at, t_.size(), p + 1);
            if (!right) continue;
            const std::optional<Folded> folded = fold(op.text, *left, *right);
            if (!folded || !folded->undefinedInGlsl) continue;
            edits.push_back(replace(*start, at, folded->value));
        }
        return outermostEdits(std::move(edits));
    }

private:
    // `const [precision] int|uint NAME = expr (, NAME = expr)* ;` read once each. A name declared
    // in any other way too is not used (it may be shadowed).
    void collectConstants() {
        std::map<std::string_view, int> declarations = countDeclarations(t_);
        for (std::size_t i = 0; i + 4 < t_.size(); ++i) {
            if (t_[i].directive || t_[i].text != "const") continue;
            std::size_t j = i + 1;
            if (t_[j].text == "highp" || t_[j].text == "mediump" || t_[j].text == "lowp") ++j;
            if (j >= t_.size()) continue;
            bool isUint = t_[j].text == "uint";
            int size = t_[j].text == "int" || isUint ? 1 : integerVectorSize(t_[j].text, isUint);
            if (size == 0) continue;
            ++j;
            while (j + 2 < t_.size() && t_[j].kind == Kind::Identifier && t_[j + 1].text == "=") {
                const std::string_view name = t_[j].text;
                std::size_t at = j + 2;
                std::optional<Value> v = parse(at, t_.size(), 1);
                if (v && v->isUint == isUint && v->size == size && declarations[name] <= 1 && constants_.count(name) == 0)
                    constants_[name] = *v;
                else
                    ambiguous_.insert(name);
                while (at < t_.size() && t_[at].text != "," && t_[at].text != ";") ++at;
                if (at >= t_.size() || t_[at].text == ";") break;
                j = at + 1;
            }
        }
        for (std::string_view name : ambiguous_) constants_.erase(name);
    }

    // The first token of the left operand of the binary operator at `op`, whose binding strength
    // is `p`: back over operands and operators that bind at least as tightly.
    std::optional<std::size_t> leftOperandStart(std::size_t op, int p) const {
        std::size_t start = op;
        std::size_t j = op;
        constexpr std::size_t kLongestOperand = 4096;  // tokens; longer left operands are left alone
        while (true) {
            if (op - j > kLongestOperand) return std::nullopt;
            // An operand: a primary with its call parentheses, then its unary operators.
            if (j == 0) return std::nullopt;
            --j;
            if (!postfixStart(j, op)) return std::nullopt;
            start = j;
            while (j > 0 && (t_[j - 1].text == "-" || t_[j - 1].text == "+" || t_[j - 1].text == "~") &&
                   !(j > 1 && endsOperand(t_[j - 2]))) {
                --j;
                start = j;
            }
            // A binary operator binding at least as tightly continues the operand.
            if (j == 0) return start;
            const GlslToken& before = t_[j - 1];
            if (before.directive || before.kind != Kind::Punct || glslBinaryStrength(before.text) < p) return start;
            --j;
        }
    }

    // Moves `j` from the last token of a postfix expression (a literal, a name, a call, each with
    // members, swizzles and indices: `CV.x`, `a[1]`) back to its first; false when it is not one.
    bool postfixStart(std::size_t& j, std::size_t op) const {
        constexpr std::size_t kLongestOperand = 4096;
        while (true) {
            const GlslToken& last = t_[j];
            if (last.directive) return false;
            if (last.text == ")" || last.text == "]") {
                const std::string_view open = last.text == ")" ? "(" : "[";
                int depth = 0;
                while (true) {
                    if (t_[j].directive || op - j > kLongestOperand) return false;
                    if (t_[j].text == last.text) ++depth;
                    else if (t_[j].text == open && --depth == 0) break;
                    if (j == 0) return false;
                    --j;
                }
                if (open == "[") {
                    if (j == 0) return false;
                    --j;  // the indexed expression
                    continue;
                }
                if (j > 0 && t_[j - 1].kind == Kind::Identifier && !isKeyword(t_[j - 1].text)) --j;
            } else if (!(last.kind == Kind::Number || (last.kind == Kind::Identifier && !isKeyword(last.text)))) {
                return false;
            }
            if (j < 2 || t_[j - 1].text != ".") return true;
            j -= 2;  // a member or swizzle of what precedes the `.`
        }
    }

    // Evaluates the expression at `at` (before `end`) made of operators binding at least `minP`;
    // `at` moves past it. nullopt when any part of it is not a constant this module reads.
    std::optional<Value> parse(std::size_t& at, std::size_t end, int minP) const {
        std::optional<Value> left = unary(at, end);
        if (!left) return std::nullopt;
        while (at < end && t_[at].directive == inDirective_ && t_[at].kind == Kind::Punct) {
            const std::string_view op = t_[at].text;
            const int p = glslBinaryStrength(op);
            if (p == 0 || p < minP) break;
            if (at + 1 < end && t_[at + 1].text == "=" && t_[at + 1].offset == t_[at].offset + op.size())
                return std::nullopt;  // a compound assignment
            ++at;
            std::optional<Value> right = parse(at, end, p + 1);
            if (!right) return std::nullopt;
            std::optional<Folded> folded = fold(op, *left, *right);
            if (!folded) return std::nullopt;
            left = folded->value;
        }
        if (at < end && (t_[at].text == "." || t_[at].text == "[" || t_[at].text == "(" || t_[at].text == "++" ||
                         t_[at].text == "--"))
            return std::nullopt;  // a member, an index, a call or an increment: not a scalar constant
        return left;
    }

    std::optional<Value> unary(std::size_t& at, std::size_t end) const {
        if (at >= end || t_[at].directive != inDirective_) return std::nullopt;
        // Bounds on any text: the stack (nesting) and the time (steps: a few per token is plenty
        // for real code; an adversarial text gets its remaining operations left to the driver).
        if (nesting_ > kMostNesting || ++steps_ > stepBudget_) return std::nullopt;
        struct Nested {
            int& n;
            explicit Nested(int& level) : n(++level) {}
            ~Nested() { --n; }
        } nested(nesting_);
        const GlslToken& t = t_[at];
        if (t.text == "-" || t.text == "+" || t.text == "~") {
            ++at;
            std::optional<Value> v = unary(at, end);
            if (!v) return std::nullopt;
            for (std::uint32_t& c : v->bits) c = t.text == "-" ? 0u - c : t.text == "~" ? ~c : c;
            return v;
        }
        std::optional<Value> v = primary(at, end);
        // Swizzles and constant indices of a constant vector (`CV.x`, `CV.yx`, `CV[1]`).
        while (v && v->size > 1 && at + 1 < end && t_[at + 1].directive == inDirective_) {
            if (t_[at].text == "." && t_[at + 1].kind == Kind::Identifier && t_[at + 1].text.size() <= 4) {
                Value picked = *v;
                picked.size = static_cast<int>(t_[at + 1].text.size());
                for (std::size_t c = 0; c < t_[at + 1].text.size(); ++c) {
                    const int from = swizzleIndex(t_[at + 1].text[c]);
                    if (from < 0 || from >= v->size) return std::nullopt;
                    picked.bits[c] = v->bits[static_cast<std::size_t>(from)];
                }
                v = picked;
                at += 2;
            } else if (t_[at].text == "[" && at + 2 < end && t_[at + 2].text == "]") {
                const std::optional<Value> index = readLiteral(t_[at + 1].text);
                if (!index || index->bits[0] >= static_cast<std::uint32_t>(v->size)) return std::nullopt;
                v->bits[0] = v->bits[index->bits[0]];
                v->size = 1;
                at += 3;
            } else {
                break;
            }
        }
        return v;
    }

    std::optional<Value> primary(std::size_t& at, std::size_t end) const {
        const GlslToken& t = t_[at];
        if (t.kind == Kind::Number) {
            ++at;
            return readLiteral(t.text);
        }
        if (t.text == "(") {
            ++at;
            std::optional<Value> v = parse(at, end, 1);
            if (!v || at >= end || t_[at].text != ")") return std::nullopt;
            ++at;
            return v;
        }
        if (t.kind != Kind::Identifier) return std::nullopt;
        bool isUint = t.text == "uint";
        const int size = t.text == "int" || isUint ? 1 : integerVectorSize(t.text, isUint);
        if (size > 0) {
            // A constructor: every argument's components in turn (int <-> uint keeps the bits), or one
            // scalar for every component.
            if (at + 1 >= end || t_[at + 1].text != "(") return std::nullopt;
            at += 2;
            Value made;
            made.isUint = isUint;
            made.size = size;
            int filled = 0;
            bool broadcast = false;
            for (int argument = 0;; ++argument) {
                const std::optional<Value> v = parse(at, end, 1);
                if (!v || at >= end) return std::nullopt;
                if (argument == 0 && v->size == 1 && t_[at].text == ")") broadcast = true;
                for (int c = 0; c < v->size && filled < size; ++c)
                    made.bits[static_cast<std::size_t>(filled++)] = v->bits[static_cast<std::size_t>(c)];
                if (t_[at].text == ")") break;
                if (t_[at].text != ",") return std::nullopt;
                ++at;
            }
            ++at;
            if (broadcast) made.bits.fill(made.bits[0]);
            else if (filled < size) return std::nullopt;
            return made;
        }
        if (const auto found = constants_.find(t.text); found != constants_.end()) {
            ++at;
            return found->second;
        }
        // An object-like macro whose body is one operand (`#define Z 0`, `#define Q (7 / 2)`): the
        // browser folds the expanded text, so its value is the body's.
        const Macro* macro = macros_.find(t.text);
        if (!macro || macro->functionLike || macro->body.empty() || expanding_.count(t.text)) return std::nullopt;
        expanding_.insert(t.text);
        const bool wasInDirective = inDirective_;
        inDirective_ = true;
        std::size_t bodyAt = macro->bodyFirst;
        const std::size_t bodyEnd = macro->bodyFirst + macro->body.size();
        std::optional<Value> v = unary(bodyAt, bodyEnd);
        inDirective_ = wasInDirective;
        expanding_.erase(t.text);
        if (!v || bodyAt != bodyEnd) return std::nullopt;
        ++at;
        return v;
    }

    static std::string componentText(const Value& v, std::size_t c) {
        if (v.isUint) return std::to_string(v.bits[c]) + "u";
        const std::int32_t n = v.asInt(static_cast<int>(c));
        return n == std::numeric_limits<std::int32_t>::min() ? "(-2147483647-1)" : std::to_string(n);
    }

    ConstantFoldEdit replace(std::size_t first, std::size_t past, Value v) const {
        const char* begin = t_[first].text.data();
        const char* stop = t_[past - 1].text.data() + t_[past - 1].text.size();
        const std::string_view span(begin, static_cast<std::size_t>(stop - begin));
        ConstantFoldEdit e;
        e.offset = t_[first].offset;
        e.erase = span.size();
        // A scalar here is ANGLE's INT_MAX, UINT_MAX or 0: never negative, so never in need of
        // parentheses; a vector is its constructor.
        if (v.size == 1) {
            e.text = componentText(v, 0);
        } else {
            e.text = std::string(v.isUint ? "uvec" : "ivec") + std::to_string(v.size) + "(";
            for (std::size_t c = 0; c < static_cast<std::size_t>(v.size); ++c) e.text += (c ? ", " : "") + componentText(v, c);
            e.text += ")";
        }
        e.text.append(static_cast<std::size_t>(std::count(span.begin(), span.end(), '\n')), '\n');
        return e;
    }

    static constexpr int kMostNesting = 1024;
    const std::vector<GlslToken>& t_;
    mutable int nesting_ = 0;
    mutable std::size_t steps_ = 0;
    std::size_t stepBudget_ = 64 * t_.size() + 100000;
    std::map<std::string_view, Value> constants_;
    std::set<std::string_view> ambiguous_;
    MacroTable macros_;
    mutable std::set<std::string_view> expanding_;  // macros being read (a macro naming itself)
    mutable bool inDirective_ = false;              // reading a macro's body
};

}  // namespace

std::vector<ConstantFoldEdit> outermostEdits(std::vector<ConstantFoldEdit> edits) {
    std::sort(edits.begin(), edits.end(), [](const ConstantFoldEdit& a, const ConstantFoldEdit& b) {
        return a.offset != b.offset ? a.offset < b.offset : a.erase > b.erase;
    });
    std::vector<ConstantFoldEdit> kept;
    std::size_t coveredTo = 0;
    for (ConstantFoldEdit& e : edits) {
        if (!kept.empty() && e.offset < coveredTo) continue;
        coveredTo = e.offset + e.erase;
        kept.push_back(std::move(e));
    }
    return kept;
}

std::map<std::string_view, int> countDeclarations(const std::vector<GlslToken>& tokens) {
    std::map<std::string_view, int> declarations;
    std::size_t scanned = 0;  // the statement read for comma-declared names ends here
    for (std::size_t i = 1; i < tokens.size(); ++i) {
        if (tokens[i].kind != Kind::Identifier || tokens[i - 1].kind != Kind::Identifier || isKeyword(tokens[i - 1].text))
            continue;
        ++declarations[tokens[i].text];  // `TYPE NAME`: a variable, parameter or function
        if (i < scanned) continue;
        // The names declared after a comma in the same statement (`int a = 2, ZC = 2;`, also in
        // a for-init) shadow a constant as well: the browser divides by the local's 2.
        int depth = 0;
        std::size_t j = i + 1;
        for (; j + 1 < tokens.size(); ++j) {
            const std::string_view w = tokens[j].text;
            if (w == "(" || w == "[") ++depth;
            else if ((w == ")" || w == "]") && --depth < 0) break;
            else if (w == ";" || w == "{" || w == "}") break;
            else if (w == "," && depth == 0 && tokens[j + 1].kind == Kind::Identifier) ++declarations[tokens[j + 1].text];
        }
        scanned = j;
    }
    return declarations;
}

std::vector<ConstantFoldEdit> foldUndefinedIntegerConstants(const std::vector<GlslToken>& tokens) {
    return Folder(tokens).run();
}

}  // namespace toyhost
