#include "shader/LoopCap.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "shader/GlslTokens.h"

namespace toyhost {

namespace {

using Kind = GlslToken::Kind;

class LoopReader {
public:
    explicit LoopReader(std::string_view text) : text_(text) {
        const std::vector<GlslToken> all = tokenizeGlsl(text);
        for (std::size_t i = 0; i < all.size(); ++i) {
            if (!all[i].directive) {
                code_.push_back(all[i]);
                continue;
            }
            // `#define NAME number` (one token after the name, not `NAME(`).
            if (all[i].directiveStart && i + 3 < all.size() && all[i + 1].text == "define" && all[i + 3].directive &&
                !all[i + 3].directiveStart && all[i + 3].kind == Kind::Number &&
                (i + 4 == all.size() || !all[i + 4].directive || all[i + 4].directiveStart) &&
                all[i + 2].offset + all[i + 2].text.size() < all[i + 3].offset)
                if (std::optional<double> v = number(all[i + 3].text)) define(all[i + 2].text, *v);
        }
        // `const TYPE NAME = constant;`, in the order they are declared.
        for (std::size_t k = 0; k + 4 < code_.size(); ++k) {
            if (code_[k].text != "const") continue;
            std::size_t n = k + 1;
            while (n < code_.size() && (code_[n].text == "highp" || code_[n].text == "mediump" || code_[n].text == "lowp")) ++n;
            if (n + 3 >= code_.size() || code_[n + 1].kind != Kind::Identifier || code_[n + 2].text != "=") continue;
            std::size_t end = n + 3;
            while (end < code_.size() && code_[end].text != ";" && code_[end].text != ",") ++end;
            if (std::optional<double> v = evaluate(n + 3, end)) define(code_[n + 1].text, *v);
        }
    }

    std::vector<CountedLoop> loops() {
        struct Open {
            std::size_t end;  // the index of the body's last token
            std::int64_t product;
            std::int64_t total;
        };
        std::vector<Open> around;
        std::vector<CountedLoop> found;
        for (std::size_t k = 0; k + 1 < code_.size(); ++k) {
            while (!around.empty() && k > around.back().end) around.pop_back();
            if (code_[k].text != "for" || code_[k + 1].text != "(") continue;
            const std::size_t close = matching(k + 1);
            if (close >= code_.size()) continue;
            const std::optional<std::int64_t> count = iterations(k + 2, close);
            if (!count) continue;
            const std::int64_t outerProduct = around.empty() ? 1 : around.back().product;
            const std::int64_t outerTotal = around.empty() ? 0 : around.back().total;
            const std::int64_t product = saturatingProduct(outerProduct, *count);
            const std::int64_t total = std::min<std::int64_t>(outerTotal + product, kHuge);
            found.push_back({lineOf(k), *count, total});
            around.push_back({bodyEnd(close + 1), product, total});
        }
        return found;
    }

private:
    static constexpr std::int64_t kHuge = std::int64_t(1) << 50;

    static std::int64_t saturatingProduct(std::int64_t a, std::int64_t b) {
        return (b != 0 && a > kHuge / b) ? kHuge : std::min(a * b, kHuge);
    }

    void define(std::string_view name, double value) {
        if (!values_.emplace(name, value).second) values_[name] = std::nan("");  // declared twice: unknown
    }

    static std::optional<double> number(std::string_view literal) {
        std::string s(literal);
        if (!s.empty() && (s.back() == 'u' || s.back() == 'U' || s.back() == 'f' || s.back() == 'F') &&
            s.find_first_of("xX") == std::string::npos)
            s.pop_back();
        try {
            std::size_t used = 0;
            const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
            const double v = hex ? static_cast<double>(std::stoll(s, &used, 16)) : std::stod(s, &used);
            if (used != s.size()) return std::nullopt;
            return v;
        } catch (...) {
            return std::nullopt;
        }
    }

    int lineOf(std::size_t k) const {
        return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(code_[k].offset), '\n'));
    }

    // The index of the `)` that closes the `(` at `k` (code_.size() when none).
    std::size_t matching(std::size_t k) const {
        int depth = 0;
        for (; k < code_.size(); ++k) {
            if (code_[k].text == "(" || code_[k].text == "[" || code_[k].text == "{") ++depth;
            else if ((code_[k].text == ")" || code_[k].text == "]" || code_[k].text == "}") && --depth == 0) return k;
        }
        return code_.size();
    }

    // The last token of the statement starting at `k` (a loop's body).
    std::size_t bodyEnd(std::size_t k) const {
        if (k >= code_.size()) return code_.size();
        if (code_[k].text == "{") return matching(k);
        if (code_[k].text == "for" || code_[k].text == "while") {
            if (k + 1 < code_.size() && code_[k + 1].text == "(") return bodyEnd(matching(k + 1) + 1);
        }
        if (code_[k].text == "if" && k + 1 < code_.size() && code_[k + 1].text == "(") {
            std::size_t end = bodyEnd(matching(k + 1) + 1);
            if (end + 1 < code_.size() && code_[end + 1].text == "else") end = bodyEnd(end + 2);
            return end;
        }
        int depth = 0;
        for (; k < code_.size(); ++k) {
            const std::string_view t = code_[k].text;
            if (t == "(" || t == "[") ++depth;
            else if (t == ")" || t == "]") --depth;
            else if (t == ";" && depth == 0) return k;
        }
        return code_.size();
    }

    // The value of the constant expression [b, e), or none.
    std::optional<double> evaluate(std::size_t b, std::size_t e) const {
        std::size_t k = b;
        const std::optional<double> v = binary(k, e, 0);
        if (!v || k != e || std::isnan(*v)) return std::nullopt;
        return v;
    }

    std::optional<double> binary(std::size_t& k, std::size_t e, int minStrength) const {
        std::optional<double> left = unary(k, e);
        while (left && k < e) {
            const std::string_view op = code_[k].text;
            const int strength = (op == "*" || op == "/") ? 2 : (op == "+" || op == "-") ? 1 : 0;
            if (strength == 0 || strength < minStrength) break;
            ++k;
            const std::optional<double> right = binary(k, e, strength + 1);
            if (!right) return std::nullopt;
            if (op == "*") *left *= *right;
            else if (op == "/") {
                if (*right == 0) return std::nullopt;
                *left /= *right;
            } else if (op == "+") *left += *right;
            else *left -= *right;
        }
        return left;
    }

    std::optional<double> unary(std::size_t& k, std::size_t e) const {
        if (k >= e) return std::nullopt;
        const GlslToken& t = code_[k];
        if (t.text == "-" || t.text == "+") {
            ++k;
            std::optional<double> v = unary(k, e);
            if (v && t.text == "-") *v = -*v;
            return v;
        }
        if (t.text == "(") {
            const std::size_t close = matching(k);
            if (close >= e) return std::nullopt;
            std::optional<double> v = evaluate(k + 1, close);
            k = close + 1;
            return v;
        }
        if (t.kind == Kind::Number) {
            ++k;
            return number(t.text);
        }
        if (t.kind != Kind::Identifier) return std::nullopt;
        if ((t.text == "int" || t.text == "uint" || t.text == "float") && k + 1 < e && code_[k + 1].text == "(") {
            const std::size_t close = matching(k + 1);
            if (close >= e) return std::nullopt;
            std::optional<double> v = evaluate(k + 2, close);
            if (v && t.text != "float") *v = std::trunc(*v);
            k = close + 1;
            return v;
        }
        const auto found = values_.find(t.text);
        if (found == values_.end()) return std::nullopt;
        ++k;
        return found->second;
    }

    // The iterations of `for (init; condition; step)` between `b` and `close`, or none.
    std::optional<std::int64_t> iterations(std::size_t b, std::size_t close) const {
        std::size_t first = b;
        while (first < close && code_[first].text != ";") ++first;
        std::size_t second = first + 1;
        while (second < close && code_[second].text != ";") ++second;
        if (second >= close) return std::nullopt;
        // init: [type] i = A
        std::size_t k = b;
        if (k < first && (code_[k].text == "int" || code_[k].text == "uint" || code_[k].text == "float")) ++k;
        if (k + 2 > first || code_[k].kind != Kind::Identifier || code_[k + 1].text != "=") return std::nullopt;
        const std::string_view name = code_[k].text;
        const std::optional<double> start = evaluate(k + 2, first);
        // condition: i op B, or B op i
        k = first + 1;
        if (second - k < 3) return std::nullopt;
        std::string_view op;
        std::optional<double> bound;
        if (code_[k].text == name) {
            op = code_[k + 1].text;
            bound = evaluate(k + 2, second);
        } else if (code_[second - 1].text == name) {
            const std::string_view reversed = code_[second - 2].text;
            op = reversed == "<" ? ">" : reversed == ">" ? "<" : reversed == "<=" ? ">=" : reversed == ">=" ? "<=" : reversed;
            bound = evaluate(k, second - 2);
        }
        // step: i++, ++i, i--, --i, i += C, i -= C
        std::optional<double> step;
        const std::size_t s = second + 1;
        const std::size_t length = close - s;
        if (length == 2 && ((code_[s].text == name && code_[s + 1].text == "++") || (code_[s].text == "++" && code_[s + 1].text == name)))
            step = 1;
        else if (length == 2 && ((code_[s].text == name && code_[s + 1].text == "--") || (code_[s].text == "--" && code_[s + 1].text == name)))
            step = -1;
        else if (length >= 3 && code_[s].text == name && (code_[s + 1].text == "+=" || code_[s + 1].text == "-=")) {
            step = evaluate(s + 2, close);
            if (step && code_[s + 1].text == "-=") *step = -*step;
        }
        if (!start || !bound || !step || *step == 0) return std::nullopt;
        const double a = *start, limit = *bound, c = *step;
        double count = 0;
        if (op == "<" && c > 0) count = std::ceil((limit - a) / c);
        else if (op == "<=" && c > 0) count = std::floor((limit - a) / c) + 1;
        else if (op == ">" && c < 0) count = std::ceil((a - limit) / -c);
        else if (op == ">=" && c < 0) count = std::floor((a - limit) / -c) + 1;
        else if (op == "!=" && std::fmod(limit - a, c) == 0 && (limit - a) / c > 0) count = (limit - a) / c;
        else return std::nullopt;
        if (!(count > 0)) return std::int64_t{0};
        return static_cast<std::int64_t>(std::min(count, static_cast<double>(kHuge)));
    }

    std::string_view text_;
    std::vector<GlslToken> code_;
    std::map<std::string_view, double> values_;
};

}  // namespace

std::vector<CountedLoop> countedLoops(std::string_view code) { return LoopReader(code).loops(); }

std::vector<Diagnostic> loopCapWarnings(const ManifestDesc& manifest) {
    std::vector<Diagnostic> warnings;
    auto check = [&](std::string_view code, const std::string& file, const std::string& pass) {
        for (const CountedLoop& loop : countedLoops(code)) {
            if (loop.total <= kLlvmpipeLoopIterations) continue;
            Diagnostic d;
            d.severity = Severity::Warning;
            // [shader.loop-cap], a warning: the driver compiles the loop and runs it differently.
            d.code = Code::ShaderLoopCap;
            d.file = file;
            d.pass = pass;
            d.line = loop.line;
            const std::string total = std::to_string(loop.total);
            d.message = "llvmpipe's loop cap: this loop runs " + total + " iterations per pixel" +
                        (loop.total != loop.iterations ? " with the loops around it" : "") +
                        "; the site runs them all, but llvmpipe (Mesa) ends a pixel's loops after " +
                        std::to_string(kLlvmpipeLoopIterations) +
                        " iterations in total, so here it stops early and later loops of the pixel run once";
            warnings.push_back(std::move(d));
        }
    };
    if (manifest.commonSource) check(manifest.commonCode, manifest.commonSource->string(), "Common");
    for (const PassDesc& pass : manifest.passes) check(pass.code, pass.sourceName, passName(pass.id));
    if (manifest.sound) check(manifest.sound->code, manifest.sound->sourceName, passName(manifest.sound->id));
    return warnings;
}

}  // namespace toyhost
