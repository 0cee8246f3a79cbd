#include "shader/OpaqueDivisors.h"

#include <cstdlib>
#include <optional>
#include <utility>

#include "shader/IntegerConstantFold.h"

namespace toyhost {

namespace {

using Kind = GlslToken::Kind;

bool isUnaryPrefix(std::string_view t) { return t == "-" || t == "+" || t == "!" || t == "~" || t == "++" || t == "--"; }

class DivisorFinder {
public:
    explicit DivisorFinder(const std::vector<GlslToken>& all) {
        for (const GlslToken& t : all)
            if (!t.directive) code_.push_back(t);
        for (const ConstantFoldEdit& fold : foldUndefinedIntegerConstants(all))
            folded_.push_back({fold.offset, fold.offset + fold.erase});
    }

    std::vector<DivisorInsertion> run() {
        std::vector<Frame> braces;
        int brackets = 0;          // depth of `[`: array sizes and indices
        bool constant = false;     // inside a `const` declaration or a `case` label
        for (std::size_t k = 0; k < code_.size(); ++k) {
            const std::string_view t = code_[k].text;
            const bool inFunction = !braces.empty() && braces.front() == Frame::Function;
            if (t == "{") {
                constant = false;  // a `const` parameter's
                braces.push_back(braces.empty() && k > 0 && code_[k - 1].text == ")" ? Frame::Function : Frame::Other);
            } else if (t == "}") {
                if (!braces.empty()) braces.pop_back();
                constant = false;
            } else if (t == "[") {
                ++brackets;
            } else if (t == "]") {
                if (brackets > 0) --brackets;
            } else if (t == "const" || t == "case") {
                constant = true;
            } else if (t == ";" || (t == ":" && constant && !inConstDeclaration(k))) {
                constant = false;
            } else if (!inFunction || brackets > 0 || constant || insideFold(code_[k].offset)) {
                continue;
            } else if (t == "/") {
                if (std::size_t end = unaryEnd(k + 1); end > k + 1 && !nothingToHide(k + 1, end)) wrap(k + 1, end);
            } else if (t == "/=") {
                if (std::size_t end = argumentEnd(k + 1); end < code_.size() && end > k + 1 && !nothingToHide(k + 1, end)) wrap(k + 1, end);
            } else if (k + 1 < code_.size() && code_[k + 1].text == "(" && (k == 0 || code_[k - 1].text != ".")) {
                builtinDivisor(k);
            }
        }
        return std::move(insertions_);
    }

private:
    enum class Frame { Function, Other };

    // A built-in called at `k` whose lowering in Mesa divides by an argument: that argument.
    // smoothstep(e0, e1, x) divides by e1 - e0; mod(x, y) is x - y * floor(x / y); atan(y, x)
    // divides by max(|x|, |y|); atanh(x) by 1 - x; inverse(m) by its determinant.
    void builtinDivisor(std::size_t k) {
        const std::string_view name = code_[k].text;
        const bool second = name == "smoothstep" || name == "mod" || name == "atan";
        if (!second && name != "atanh" && name != "inverse") return;
        const std::size_t firstBegin = k + 2;
        std::size_t begin = firstBegin;
        std::size_t end = argumentEnd(begin);
        const std::size_t firstEnd = end;
        if (second) {
            if (end >= code_.size() || code_[end].text != ",") return;
            begin = end + 1;
            end = argumentEnd(begin);
            if (name == "atan" && (end >= code_.size() || code_[end].text != ")")) return;
        }
        if (end >= code_.size() || end == begin) return;
        // A literal y or x is safe for mod and atan; smoothstep's divisor is the edges'
        // difference, safe only for two different literals (the common smoothstep(0.0, 1.0, x)).
        if ((name == "mod" || name == "atan") && nothingToHide(begin, end)) return;
        if (name == "smoothstep") {
            const std::optional<double> e0 = literal(firstBegin, firstEnd), e1 = literal(begin, end);
            if (e0 && e1 && *e0 != *e1) return;
        }
        wrap(begin, end);
    }

    // The value of a number literal with its signs between `begin` and `end`, or none.
    std::optional<double> literal(std::size_t begin, std::size_t end) const {
        double sign = 1.0;
        for (; begin < end && (code_[begin].text == "-" || code_[begin].text == "+"); ++begin)
            if (code_[begin].text == "-") sign = -sign;
        if (end != begin + 1 || code_[begin].kind != Kind::Number) return std::nullopt;
        std::string text(code_[begin].text);
        if (!text.empty() && (text.back() == 'f' || text.back() == 'F')) text.pop_back();
        char* stop = nullptr;
        const double value = std::strtod(text.c_str(), &stop);
        if (stop != text.c_str() + text.size()) return std::nullopt;
        return sign * value;
    }

    // `case` labels end at `:`; a `const` declaration ends only at `;` (a `?:` inside it must not
    // end it).
    bool inConstDeclaration(std::size_t k) const {
        for (std::size_t i = k; i-- > 0;) {
            if (code_[i].text == "case") return false;
            if (code_[i].text == "const") return true;
        }
        return false;
    }

    bool insideFold(std::size_t offset) const {
        for (const auto& [begin, end] : folded_)
            if (offset >= begin && offset < end) return true;
        return false;
    }

    // The index after the bracket that matches the one at `k` (code_.size() when unmatched).
    std::size_t skipGroup(std::size_t k) const {
        int depth = 0;
        for (; k < code_.size(); ++k) {
            const std::string_view t = code_[k].text;
            if (t == "(" || t == "[") ++depth;
            else if ((t == ")" || t == "]") && --depth == 0) return k + 1;
        }
        return code_.size();
    }

    // The end (exclusive) of the unary expression starting at `k`: prefix operators, a primary
    // (a name, a number, a parenthesised group, a call or constructor, `float[2](...)`), then
    // postfix `[...]`, `.name`, `.length()`, `++`, `--`. `k` when none starts there.
    std::size_t unaryEnd(std::size_t k) const {
        const std::size_t start = k;
        const std::size_t n = code_.size();
        while (k < n && isUnaryPrefix(code_[k].text)) ++k;
        if (k >= n) return start;
        if (code_[k].text == "(") {
            k = skipGroup(k);
        } else if (code_[k].kind == Kind::Identifier || code_[k].kind == Kind::Number) {
            const bool name = code_[k].kind == Kind::Identifier;
            ++k;
            if (name && k < n && code_[k].text == "[") {
                const std::size_t after = skipGroup(k);
                if (after < n && code_[after].text == "(") k = after;  // an array constructor
            }
            if (name && k < n && code_[k].text == "(") k = skipGroup(k);
        } else {
            return start;
        }
        while (k < n) {
            const std::string_view t = code_[k].text;
            if (t == "[") k = skipGroup(k);
            else if (t == "." && k + 1 < n && code_[k + 1].kind == Kind::Identifier) {
                k += 2;
                if (k < n && code_[k].text == "(") k = skipGroup(k);
            } else if (t == "++" || t == "--") ++k;
            else break;
        }
        return k > n ? n : k;
    }

    // The end of an argument or of an assignment's right-hand side starting at `k`: the `,`, `;`
    // or unmatched `)` that closes it at its own depth.
    std::size_t argumentEnd(std::size_t k) const {
        int depth = 0;
        for (; k < code_.size(); ++k) {
            const std::string_view t = code_[k].text;
            if (t == "(" || t == "[") ++depth;
            else if (t == ")" || t == "]") {
                if (depth-- == 0) return k;
            } else if (t == "," && depth == 0) return k;
            else if (depth == 0 && (t == ";" || t == "{" || t == "}")) return k;
        }
        return code_.size();
    }

    // A divisor that is one number literal (with a sign), except a zero: an integer literal is an
    // integer division (left to shader/IntegerConstantFold), and a non-zero float constant is
    // safe to fold.
    bool nothingToHide(std::size_t begin, std::size_t end) const {
        while (begin < end && (code_[begin].text == "-" || code_[begin].text == "+")) ++begin;
        if (end != begin + 1 || code_[begin].kind != Kind::Number) return false;
        const std::string_view literal = code_[begin].text;
        const bool isFloat = literal.find_first_of(".eE") != std::string_view::npos && literal.find_first_of("xX") == std::string_view::npos;
        if (!isFloat) return true;
        for (char c : literal) {
            if (c == 'e' || c == 'E') break;
            if (c >= '1' && c <= '9') return true;
        }
        return false;
    }

    void wrap(std::size_t begin, std::size_t end) {
        insertions_.push_back({code_[begin].offset, std::string(kOpaqueFunction) + "(", false});
        insertions_.push_back({code_[end - 1].offset + code_[end - 1].text.size(), ")", true});
    }

    std::vector<GlslToken> code_;
    std::vector<std::pair<std::size_t, std::size_t>> folded_;  // byte spans IntegerConstantFold replaces
    std::vector<DivisorInsertion> insertions_;
};

}  // namespace

std::vector<DivisorInsertion> opaqueDivisors(const std::vector<GlslToken>& tokens) { return DivisorFinder(tokens).run(); }

std::string opaqueDivisorDeclarations(std::string_view user) {
    if (opaqueDivisors(tokenizeGlsl(user)).empty()) return {};
    const std::string f = kOpaqueFunction;
    std::string out = std::string("uniform uint ") + kZeroUniform + ";\n";
    for (const char* type : {"float", "vec2", "vec3", "vec4"})
        out.append(type).append(" ").append(f).append("(").append(type).append(" x) { return uintBitsToFloat(floatBitsToUint(x) ^ ")
            .append(kZeroUniform).append("); }\n");
    // matCxR: C columns of R rows.
    for (const char* type : {"mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2",
                             "mat4x3", "mat4x4"}) {
        const std::string_view t = type;
        if (t.size() == 6 && (t == "mat2x2" || t == "mat3x3" || t == "mat4x4")) continue;  // the same types as mat2..4
        const int columns = t[3] - '0';
        out.append(type).append(" ").append(f).append("(").append(type).append(" x) { return ").append(type).append("(");
        for (int c = 0; c < columns; ++c) out.append(c ? ", " : "").append(f).append("(x[").append(std::to_string(c)).append("])");
        out.append("); }\n");
    }
    for (const char* type : {"int", "ivec2", "ivec3", "ivec4", "uint", "uvec2", "uvec3", "uvec4"})
        out.append(type).append(" ").append(kOpaqueFunction).append("(").append(type).append(" x) { return x; }\n");
    return out;
}

}  // namespace toyhost
