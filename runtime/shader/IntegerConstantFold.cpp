#include "shader/IntegerConstantFold.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string_view>

namespace toyhost {
namespace {

using Kind = GlslToken::Kind;

struct Value {
    bool isUint = false;
    std::uint32_t bits = 0;
    std::int32_t asInt() const { return static_cast<std::int32_t>(bits); }
};

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
    v.bits = static_cast<std::uint32_t>(n);
    return v;
}

// What ANGLE's folder gives for `a op b`, and whether that value is its own choice (an operation
// GLSL ES leaves undefined). nullopt for operand types GLSL refuses together.
struct Folded {
    Value value;
    bool undefinedInGlsl = false;
};

std::optional<Folded> fold(std::string_view op, Value a, Value b) {
    const bool shift = op == "<<" || op == ">>";
    if (!shift && a.isUint != b.isUint) return std::nullopt;
    Folded out;
    out.value.isUint = a.isUint;
    constexpr std::int32_t kIntMin = std::numeric_limits<std::int32_t>::min();
    constexpr std::int32_t kIntMax = std::numeric_limits<std::int32_t>::max();
    if (shift) {
        const bool valid = b.isUint ? b.bits <= 31u : (b.asInt() >= 0 && b.asInt() <= 31);
        if (!valid) {
            out.undefinedInGlsl = true;
            out.value.bits = 0;
        } else if (op == "<<") {
            out.value.bits = a.bits << b.bits;
        } else if (a.isUint || a.asInt() >= 0) {
            out.value.bits = a.bits >> b.bits;
        } else {
            out.value.bits = ~(~a.bits >> b.bits);  // the sign extends
        }
        return out;
    }
    if (op == "/" || op == "%") {
        if (b.bits == 0) {
            out.undefinedInGlsl = true;
            out.value.bits = a.isUint ? 0xFFFFFFFFu : static_cast<std::uint32_t>(kIntMax);
        } else if (a.isUint) {
            out.value.bits = op == "/" ? a.bits / b.bits : a.bits % b.bits;
        } else if (op == "/") {
            if (a.asInt() == kIntMin && b.asInt() == -1) {
                out.undefinedInGlsl = true;
                out.value.bits = static_cast<std::uint32_t>(kIntMax);
            } else {
                out.value.bits = static_cast<std::uint32_t>(a.asInt() / b.asInt());
            }
        } else if (a.asInt() < 0 || b.asInt() < 0) {
            out.undefinedInGlsl = true;
            out.value.bits = 0;
        } else {
            out.value.bits = static_cast<std::uint32_t>(a.asInt() % b.asInt());
        }
        return out;
    }
    // The rest wrap in 32 bits, for int as for uint.
    if (op == "*") out.value.bits = a.bits * b.bits;
    else if (op == "+") out.value.bits = a.bits + b.bits;
    else if (op == "-") out.value.bits = a.bits - b.bits;
    else if (op == "&") out.value.bits = a.bits & b.bits;
    else if (op == "^") out.value.bits = a.bits ^ b.bits;
    else if (op == "|") out.value.bits = a.bits | b.bits;
    else return std::nullopt;
    return out;
}

bool endsOperand(const GlslToken& t) {
    if (t.kind == Kind::Number) return true;
    if (t.kind == Kind::Identifier) return !isKeyword(t.text);
    return t.text == ")" || t.text == "]";
}

class Folder {
public:
    explicit Folder(const std::vector<GlslToken>& tokens) : t_(tokens) {}

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
        // Nested edits: keep the outermost (it starts first, or at the same token and ends later).
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

private:
    // `const [precision] int|uint NAME = expr (, NAME = expr)* ;` read once each. A name declared
    // in any other way too is not used (it may be shadowed).
    void collectConstants() {
        std::map<std::string_view, int> declarations;
        std::size_t scanned = 0;  // the statement read for comma-declared names ends here
        for (std::size_t i = 1; i < t_.size(); ++i) {
            if (t_[i].kind != Kind::Identifier || t_[i - 1].kind != Kind::Identifier || isKeyword(t_[i - 1].text)) continue;
            ++declarations[t_[i].text];  // `TYPE NAME`: a variable, parameter or function
            if (i < scanned) continue;
            // The names declared after a comma in the same statement (`int a = 2, ZC = 2;`, also in
            // a for-init) shadow a constant as well: the browser divides by the local's 2.
            int depth = 0;
            std::size_t j = i + 1;
            for (; j + 1 < t_.size(); ++j) {
                const std::string_view w = t_[j].text;
                if (w == "(" || w == "[") ++depth;
                else if ((w == ")" || w == "]") && --depth < 0) break;
                else if (w == ";" || w == "{" || w == "}") break;
                else if (w == "," && depth == 0 && t_[j + 1].kind == Kind::Identifier) ++declarations[t_[j + 1].text];
            }
            scanned = j;
        }
        for (std::size_t i = 0; i + 4 < t_.size(); ++i) {
            if (t_[i].directive || t_[i].text != "const") continue;
            std::size_t j = i + 1;
            if (t_[j].text == "highp" || t_[j].text == "mediump" || t_[j].text == "lowp") ++j;
            if (j >= t_.size() || (t_[j].text != "int" && t_[j].text != "uint")) continue;
            const bool isUint = t_[j].text == "uint";
            ++j;
            while (j + 2 < t_.size() && t_[j].kind == Kind::Identifier && t_[j + 1].text == "=") {
                const std::string_view name = t_[j].text;
                std::size_t at = j + 2;
                std::optional<Value> v = parse(at, t_.size(), 1);
                if (v && v->isUint == isUint && declarations[name] <= 1 && constants_.count(name) == 0)
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
            const GlslToken& last = t_[j];
            if (last.directive) return std::nullopt;
            if (last.text == ")") {
                int depth = 0;
                while (true) {
                    if (t_[j].directive || op - j > kLongestOperand) return std::nullopt;
                    if (t_[j].text == ")") ++depth;
                    else if (t_[j].text == "(" && --depth == 0) break;
                    if (j == 0) return std::nullopt;
                    --j;
                }
                if (j > 0 && t_[j - 1].kind == Kind::Identifier && !isKeyword(t_[j - 1].text)) --j;
            } else if (last.kind == Kind::Number || (last.kind == Kind::Identifier && !isKeyword(last.text))) {
                // a literal or a name
            } else {
                return std::nullopt;
            }
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

    // Evaluates the expression at `at` (before `end`) made of operators binding at least `minP`;
    // `at` moves past it. nullopt when any part of it is not a constant this module reads.
    std::optional<Value> parse(std::size_t& at, std::size_t end, int minP) const {
        std::optional<Value> left = unary(at, end);
        if (!left) return std::nullopt;
        while (at < end && !t_[at].directive && t_[at].kind == Kind::Punct) {
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
        if (at >= end || t_[at].directive) return std::nullopt;
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
            if (t.text == "-") v->bits = 0u - v->bits;
            else if (t.text == "~") v->bits = ~v->bits;
            return v;
        }
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
        if ((t.text == "int" || t.text == "uint") && at + 1 < end && t_[at + 1].text == "(") {
            at += 2;
            std::optional<Value> v = parse(at, end, 1);
            if (!v || at >= end || t_[at].text != ")") return std::nullopt;
            ++at;
            v->isUint = t.text == "uint";  // int <-> uint keeps the bits
            return v;
        }
        const auto found = constants_.find(t.text);
        if (found == constants_.end()) return std::nullopt;
        ++at;
        return found->second;
    }

    ConstantFoldEdit replace(std::size_t first, std::size_t past, Value v) const {
        const char* begin = t_[first].text.data();
        const char* stop = t_[past - 1].text.data() + t_[past - 1].text.size();
        const std::string_view span(begin, static_cast<std::size_t>(stop - begin));
        ConstantFoldEdit e;
        e.offset = t_[first].offset;
        e.erase = span.size();
        // ANGLE's values here are INT_MAX, UINT_MAX and 0: never negative, so never in need of
        // parentheses.
        e.text = v.isUint ? std::to_string(v.bits) + "u" : std::to_string(v.asInt());
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
};

}  // namespace

std::vector<ConstantFoldEdit> foldUndefinedIntegerConstants(const std::vector<GlslToken>& tokens) {
    return Folder(tokens).run();
}

}  // namespace toyhost
