#include "shader/TexelCornerReads.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>

#include "shader/GlslTokens.h"

namespace toyhost {

namespace {

using Kind = GlslToken::Kind;

// What the scan knows of a value: its unit (texels, like fragCoord, or uv, a texel value divided by
// the resolution) and its phase within a texel, in halves: 0 on a texel corner (integer), 1 on a
// centre (integer + 0.5). Anything else is Unknown and ends the analysis of that read.
struct Value {
    enum class Unit { Unknown, Const, Texel, Uv, Resolution } unit = Unit::Unknown;
    int phase = -1;         // 0 or 1 (halves mod 2); -1 unknown
    double scalar = NAN;    // a Const's value when it is one known number
    bool uvSum = false;     // a Uv made by adding two uv values (uv + k / resolution)
    bool unitStep = false;  // exactly 1 / resolution
};

Value unknown() { return {}; }
Value constant(int phase, double scalar = NAN) {
    Value v;
    v.unit = Value::Unit::Const;
    v.phase = phase;
    v.scalar = scalar;
    return v;
}
Value texel(int phase) {
    if (phase < 0) return unknown();
    Value v;
    v.unit = Value::Unit::Texel;
    v.phase = phase;
    return v;
}
Value uv(int phase, bool uvSum = false, bool unitStep = false) {
    if (phase < 0) return unknown();
    Value v;
    v.unit = Value::Unit::Uv;
    v.phase = phase;
    v.uvSum = uvSum;
    v.unitStep = unitStep;
    return v;
}
Value resolution() {
    Value v;
    v.unit = Value::Unit::Resolution;
    return v;
}

// The phase of a number: 0 for integers, 1 for odd multiples of 0.5, else unknown.
int phaseOf(double x) {
    const double halves = x * 2.0;
    if (!std::isfinite(halves) || halves != std::floor(halves) || std::fabs(halves) > 1e6) return -1;
    return static_cast<int>(std::fmod(std::fabs(halves), 2.0));
}
int addPhases(int a, int b) { return a < 0 || b < 0 ? -1 : (a + b) % 2; }
bool isIntegerConst(const Value& v) { return v.unit == Value::Unit::Const && v.phase == 0; }

Value add(const Value& a, const Value& b) {
    using U = Value::Unit;
    const int phase = addPhases(a.phase, b.phase);
    if (a.unit == U::Const && b.unit == U::Const)
        return constant(phase, a.scalar + b.scalar);
    if ((a.unit == U::Texel && (b.unit == U::Texel || b.unit == U::Const)) || (a.unit == U::Const && b.unit == U::Texel))
        return texel(phase);
    if (a.unit == U::Uv && b.unit == U::Uv) return uv(phase, true);
    return unknown();
}

Value negate(Value v) {
    v.scalar = -v.scalar;  // the phase of -x is the phase of x (halves mod 2)
    v.unitStep = false;
    return v;
}

Value multiply(const Value& a, const Value& b) {
    using U = Value::Unit;
    if (a.unit == U::Const && (a.scalar == 1.0 || a.scalar == -1.0)) return a.scalar == 1.0 ? b : negate(b);
    if (b.unit == U::Const && (b.scalar == 1.0 || b.scalar == -1.0)) return b.scalar == 1.0 ? a : negate(a);
    if (a.unit == U::Const && b.unit == U::Const) {
        const double product = a.scalar * b.scalar;
        return constant(std::isnan(product) ? -1 : phaseOf(product), product);
    }
    if ((a.unit == U::Uv && b.unit == U::Resolution) || (a.unit == U::Resolution && b.unit == U::Uv))
        return texel(a.unit == U::Uv ? a.phase : b.phase);
    // k * (1 / resolution): k texels in uv units.
    for (const auto& [step, k] : {std::pair{&a, &b}, std::pair{&b, &a}})
        if (step->unit == U::Uv && step->unitStep && (k->unit == U::Texel || k->unit == U::Const)) return uv(k->phase);
    // An integer count of texels keeps a corner a corner; a centre times an odd integer stays one.
    for (const auto& [t, k] : {std::pair{&a, &b}, std::pair{&b, &a}})
        if (t->unit == U::Texel && isIntegerConst(*k) && !std::isnan(k->scalar))
            return texel(t->phase == 0 ? 0 : phaseOf(0.5 * k->scalar));
    return unknown();
}

Value divide(const Value& a, const Value& b) {
    using U = Value::Unit;
    if (b.unit == U::Resolution) {
        if (a.unit == U::Texel) return uv(a.phase);
        if (a.unit == U::Const) return uv(a.phase, false, a.scalar == 1.0);
        return unknown();
    }
    if (b.unit == U::Const && b.scalar == 1.0) return a;
    if (a.unit == U::Const && b.unit == U::Const) {
        const double quotient = a.scalar / b.scalar;
        return constant(std::isnan(quotient) ? -1 : phaseOf(quotient), quotient);
    }
    return unknown();
}

bool isIntegerType(std::string_view w) {
    return w == "int" || w == "uint" || w == "ivec2" || w == "ivec3" || w == "ivec4" || w == "uvec2" || w == "uvec3" ||
           w == "uvec4";
}
bool isFloatType(std::string_view w) { return w == "float" || w == "vec2" || w == "vec3" || w == "vec4"; }
bool isAssignment(std::string_view w) { return w == "=" || w == "+=" || w == "-=" || w == "*=" || w == "/="; }

// A recursive-descent reading of one expression's tokens [pos, end), GLSL precedence for + - * /.
class Reader {
public:
    Reader(const std::vector<GlslToken>& tokens, const std::map<std::string_view, Value>& names)
        : tokens_(tokens), names_(names) {}

    // The value of tokens [begin, end), unknown unless the whole range reads as one expression.
    Value read(std::size_t begin, std::size_t end) {
        pos_ = begin;
        end_ = end;
        Value v = sum();
        return pos_ == end_ ? v : unknown();
    }

private:
    std::string_view at() const { return pos_ < end_ ? tokens_[pos_].text : std::string_view(); }

    Value sum() {
        Value v = product();
        while (at() == "+" || at() == "-") {
            const bool minus = at() == "-";
            ++pos_;
            const Value rhs = product();
            v = add(v, minus ? negate(rhs) : rhs);
        }
        return v;
    }
    Value product() {
        Value v = unary();
        while (at() == "*" || at() == "/") {
            const bool over = at() == "/";
            ++pos_;
            const Value rhs = unary();
            v = over ? divide(v, rhs) : multiply(v, rhs);
        }
        return v;
    }
    Value unary() {
        if (at() == "-") return ++pos_, negate(unary());
        if (at() == "+") return ++pos_, unary();
        return postfix();
    }
    Value postfix() {
        Value v = primary();
        while (true) {
            if (at() == "." && pos_ + 1 < end_ && tokens_[pos_ + 1].kind == Kind::Identifier) {
                pos_ += 2;  // a swizzle keeps unit and phase (all components agree, as far as known)
            } else if (at() == "[") {
                ++pos_;
                skipBalanced();
            } else {
                return v;
            }
        }
    }
    // Past the bracket that closes a group already opened.
    void skipBalanced() {
        int depth = 0;
        while (pos_ < end_) {
            const std::string_view w = tokens_[pos_++].text;
            if (w == "(" || w == "[") ++depth;
            else if ((w == ")" || w == "]") && depth-- == 0) return;
        }
    }
    // The arguments of a call whose `(` is at pos_, each read on its own; pos_ ends past the `)`.
    std::vector<Value> arguments() {
        std::vector<Value> args;
        ++pos_;
        std::size_t start = pos_;
        int depth = 0;
        while (pos_ < end_) {
            const std::string_view w = tokens_[pos_].text;
            if (w == "(" || w == "[") ++depth;
            else if ((w == ")" || w == "]") && depth > 0) --depth;
            else if (depth == 0 && (w == "," || w == ")")) {
                if (pos_ > start) {
                    Reader inner(tokens_, names_);
                    args.push_back(inner.read(start, pos_));
                }
                start = ++pos_;
                if (w == ")") return args;
                continue;
            }
            ++pos_;
        }
        return {};  // unbalanced: nothing known
    }
    Value primary() {
        if (pos_ >= end_) return unknown();
        const GlslToken& t = tokens_[pos_];
        if (t.kind == Kind::Number) {
            ++pos_;
            std::string digits(t.text);
            while (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U' || digits.back() == 'f' || digits.back() == 'F'))
                digits.pop_back();
            char* stop = nullptr;
            const double x = std::strtod(digits.c_str(), &stop);
            return stop && *stop == '\0' ? constant(phaseOf(x), x) : unknown();
        }
        if (t.text == "(") {
            ++pos_;
            const std::size_t inner = pos_;
            skipBalanced();
            Reader nested(tokens_, names_);
            return nested.read(inner, pos_ - 1);
        }
        if (t.kind != Kind::Identifier) return ++pos_, unknown();
        const std::string_view name = t.text;
        ++pos_;
        if (at() == "(") return call(name, arguments());
        if (name == "iResolution" || name == "iChannelResolution") return resolution();
        if (name == "gl_FragCoord") return texel(1);
        const auto known = names_.find(name);
        return known == names_.end() ? unknown() : known->second;
    }
    Value call(std::string_view name, const std::vector<Value>& args) {
        using U = Value::Unit;
        if (name == "textureSize") return resolution();
        if (isIntegerType(name)) return texel(0);  // integers count texels: ivec2(fragCoord)
        if (args.empty()) return unknown();
        if (name == "floor" || name == "ceil" || name == "round" || name == "trunc" || name == "roundEven") {
            if (args.size() != 1) return unknown();
            if (args[0].unit == U::Texel) return texel(0);
            if (args[0].unit == U::Const) return constant(0, std::isnan(args[0].scalar) ? NAN : std::floor(args[0].scalar));
            return unknown();
        }
        if (name == "float" || name == "vec2" || name == "vec3" || name == "vec4") {
            if (args.size() == 1) return args[0];
            // Components agreeing on unit and phase: vec2(1, 0), vec2(x, y) of loop integers.
            bool anyTexel = false;
            for (const Value& a : args) {
                if ((a.unit != U::Const && a.unit != U::Texel) || a.phase != args[0].phase) return unknown();
                anyTexel = anyTexel || a.unit == U::Texel;
            }
            return anyTexel ? texel(args[0].phase) : constant(args[0].phase);
        }
        return unknown();
    }

    const std::vector<GlslToken>& tokens_;
    const std::map<std::string_view, Value>& names_;
    std::size_t pos_ = 0;
    std::size_t end_ = 0;
};

// The end of the expression starting at `begin`: the first `,` `;` or unmatched `)` at depth 0.
std::size_t expressionEnd(const std::vector<GlslToken>& tokens, std::size_t begin) {
    int depth = 0;
    for (std::size_t i = begin; i < tokens.size(); ++i) {
        const std::string_view w = tokens[i].text;
        if (w == "(" || w == "[") ++depth;
        else if (w == ")" || w == "]") {
            if (depth-- == 0) return i;
        } else if (depth == 0 && (w == "," || w == ";" || w == "{" || w == "}")) return i;
    }
    return tokens.size();
}

// The argument ranges of the call or signature whose `(` is at `open`, and the index of its `)`.
struct ArgumentRanges {
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    std::size_t close = 0;
};
ArgumentRanges argumentRanges(const std::vector<GlslToken>& tokens, std::size_t open) {
    ArgumentRanges out;
    std::size_t start = open + 1;
    int depth = 0;
    for (std::size_t i = open + 1; i < tokens.size(); ++i) {
        const std::string_view w = tokens[i].text;
        if (w == "(" || w == "[") ++depth;
        else if ((w == ")" || w == "]") && depth > 0) --depth;
        else if (depth == 0 && (w == "," || w == ")")) {
            if (i > start) out.ranges.emplace_back(start, i);
            start = i + 1;
            if (w == ")") {
                out.close = i;
                return out;
            }
        }
    }
    out.close = tokens.size();
    return out;
}

// What a helper's parameters hold, from its call sites in the pass: `float cell(vec2 o)` called
// as cell(vec2(1, 0)) and cell(vec2(x, y)) has `o` an integer offset. A parameter whose calls
// disagree, or that no call site gives, is left out (unknown).
std::map<std::string_view, Value> parameterValues(const std::vector<GlslToken>& tokens,
                                                  const std::map<std::string_view, Value>& names) {
    std::map<std::string_view, std::vector<std::string_view>> parameters;  // function -> parameter names
    std::set<std::size_t> signatures;
    int braces = 0;
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const std::string_view w = tokens[i].text;
        if (w == "{") ++braces;
        else if (w == "}") braces = std::max(0, braces - 1);
        else if (braces == 0 && tokens[i].kind == Kind::Identifier && tokens[i + 1].text == "(") {
            const ArgumentRanges signature = argumentRanges(tokens, i + 1);
            if (signature.close + 1 >= tokens.size() || tokens[signature.close + 1].text != "{") continue;
            std::vector<std::string_view>& list = parameters[w];
            list.clear();
            for (const auto& [begin, end] : signature.ranges)
                list.push_back(tokens[end - 1].kind == Kind::Identifier ? tokens[end - 1].text : std::string_view());
            signatures.insert(i);
        }
    }
    std::map<std::string_view, Value> values;
    std::set<std::string_view> disagreeing;
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const auto function = parameters.find(tokens[i].text);
        if (function == parameters.end() || tokens[i + 1].text != "(" || signatures.count(i)) continue;
        const ArgumentRanges call = argumentRanges(tokens, i + 1);
        if (call.ranges.size() != function->second.size()) continue;
        for (std::size_t a = 0; a < call.ranges.size(); ++a) {
            const std::string_view name = function->second[a];
            Reader reader(tokens, names);
            const Value v = reader.read(call.ranges[a].first, call.ranges[a].second);
            const auto seen = values.find(name);
            if (seen == values.end()) {
                values[name] = v;
                continue;
            }
            // An offset given as vec2(0) at one call and vec2(x, y) of loop integers at another is
            // an integer number of texels either way.
            const auto offsetLike = [](const Value& x) { return x.unit == Value::Unit::Texel || x.unit == Value::Unit::Const; };
            if (offsetLike(seen->second) && offsetLike(v) && seen->second.phase == v.phase) seen->second = texel(v.phase);
            else if (seen->second.unit != v.unit || seen->second.phase != v.phase || seen->second.uvSum != v.uvSum)
                disagreeing.insert(name);
        }
    }
    for (std::string_view name : disagreeing) values.erase(name);
    std::erase_if(values, [](const auto& entry) { return entry.second.unit == Value::Unit::Unknown; });
    return values;
}

// What each name means for the whole pass: integer-typed names count texels; a float name set once
// (declared with an initializer and never assigned again) has its initializer's value; fragCoord
// (mainImage's second parameter, whatever it is called) is a texel centre unless assigned;
// a helper's parameter has what `parameters` says its call sites pass.
std::map<std::string_view, Value> nameValues(const std::vector<GlslToken>& tokens,
                                             const std::map<std::string_view, Value>& parameters) {
    std::map<std::string_view, Value> names;
    std::set<std::string_view> spoiled;  // assigned after their declaration, or declared twice differently
    std::set<std::string_view> integers;
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i)
        if (isIntegerType(tokens[i].text) && tokens[i + 1].kind == Kind::Identifier) integers.insert(tokens[i + 1].text);
    for (std::string_view name : integers) names[name] = texel(0);
    std::set<std::string_view> fragCoords{"fragCoord"};  // helpers often name their parameter so
    for (std::size_t i = 0; i + 4 < tokens.size(); ++i)
        if (tokens[i].text == "mainImage" && tokens[i + 1].text == "(") {
            for (std::size_t j = i + 2; j + 1 < tokens.size() && tokens[j].text != ")"; ++j)
                if (tokens[j].text == "vec2" && tokens[j + 1].kind == Kind::Identifier) fragCoords.insert(tokens[j + 1].text);
        }
    for (std::string_view name : fragCoords) names[name] = texel(1);
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const GlslToken& t = tokens[i];
        if (t.directive || t.kind != Kind::Identifier) continue;
        const bool declared = i > 0 && (isFloatType(tokens[i - 1].text) || isIntegerType(tokens[i - 1].text));
        if (declared && isFloatType(tokens[i - 1].text) && !integers.count(t.text)) {
            if (tokens[i + 1].text != "=" && fragCoords.count(t.text)) continue;  // its parameter declaration
            Value v = unknown();
            if (const auto given = parameters.find(t.text); given != parameters.end() && tokens[i + 1].text != "=") {
                v = given->second;
            } else if (tokens[i + 1].text == "=") {
                Reader reader(tokens, names);
                v = reader.read(i + 2, expressionEnd(tokens, i + 2));
            }
            const auto before = names.find(t.text);
            const bool differs = before != names.end() && (before->second.unit != v.unit || before->second.phase != v.phase);
            if (differs || v.unit == Value::Unit::Unknown) spoiled.insert(t.text);
            names[t.text] = v;
        } else if (!declared && isAssignment(tokens[i + 1].text) && (i == 0 || tokens[i - 1].text != ".")) {
            spoiled.insert(t.text);
        } else if (!declared && (tokens[i + 1].text == "++" || tokens[i + 1].text == "--" ||
                                 (i > 0 && (tokens[i - 1].text == "++" || tokens[i - 1].text == "--")))) {
            spoiled.insert(t.text);
        }
        // A member or component written (p.x = ...) spoils the whole name.
        if (!declared && tokens[i + 1].text == "." && i + 3 < tokens.size() && isAssignment(tokens[i + 3].text))
            spoiled.insert(t.text);
    }
    for (std::string_view name : spoiled) names.erase(name);
    for (std::string_view name : integers) names[name] = texel(0);  // whatever they hold, integers
    return names;
}

int lineAt(std::string_view code, std::size_t offset) {
    return 1 + static_cast<int>(std::count(code.begin(), code.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

}  // namespace

std::vector<TexelRead> texelReads(std::string_view code) {
    std::vector<GlslToken> tokens = tokenizeGlsl(code);
    std::erase_if(tokens, [](const GlslToken& t) { return t.directive; });
    // Twice: the first reading gives what the call sites pass to helpers' parameters.
    const std::map<std::string_view, Value> names = nameValues(tokens, parameterValues(tokens, nameValues(tokens, {})));
    std::vector<TexelRead> reads;
    for (std::size_t i = 0; i + 4 < tokens.size(); ++i) {
        const std::string_view w = tokens[i].text;
        if ((w != "texture" && w != "textureLod") || tokens[i + 1].text != "(") continue;
        const std::string_view channel = tokens[i + 2].text;
        if (channel.size() != 9 || channel.substr(0, 8) != "iChannel" || channel[8] < '0' ||
            channel[8] >= '0' + kChannelCount || tokens[i + 3].text != ",")
            continue;
        const std::size_t begin = i + 4;
        const std::size_t end = expressionEnd(tokens, begin);
        Reader reader(tokens, names);
        const Value coordinate = reader.read(begin, end);
        if (coordinate.unit != Value::Unit::Uv) continue;
        TexelRead read;
        read.channel = channel[8] - '0';
        read.line = lineAt(code, tokens[i].offset);
        if (coordinate.phase == 0) read.landing = TexelLanding::Corner;
        else if (coordinate.uvSum) read.landing = TexelLanding::UvStep;
        else continue;
        reads.push_back(read);
    }
    return reads;
}

bool comparesExactly(std::string_view code) {
    // A float literal: GLSL ES has no implicit int-to-float conversion, so `iFrame == 0` is an
    // integer comparison and `n == 3.0` a float one.
    auto floatNumber = [](const GlslToken& t) {
        return t.kind == Kind::Number && t.text.find_first_of("xX") == std::string_view::npos &&
               t.text.find_first_of(".eE") != std::string_view::npos;
    };
    const std::vector<GlslToken> tokens = tokenizeGlsl(code);
    for (std::size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].directive || (tokens[i].text != "==" && tokens[i].text != "!=")) continue;
        if ((i > 0 && floatNumber(tokens[i - 1])) || (i + 1 < tokens.size() && floatNumber(tokens[i + 1]))) return true;
    }
    return false;
}

std::vector<Diagnostic> texelCornerWarnings(const ManifestDesc& manifest) {
    std::vector<Diagnostic> warnings;
    const bool commonCompares = manifest.commonSource && comparesExactly(manifest.commonCode);
    for (const PassDesc& pass : manifest.passes) {
        const std::vector<TexelRead> reads = texelReads(pass.code);
        const bool exact = commonCompares || comparesExactly(pass.code);
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& channel = pass.channels[c];
            if (channel.kind != ChannelKind::Buffer || channel.sampler.filter == Filter::Nearest) continue;
            int count = 0, first = 0;
            bool corner = false;
            for (const TexelRead& read : reads) {
                if (read.channel != c || (read.landing == TexelLanding::UvStep && !exact)) continue;
                if (count++ == 0) first = read.line;
                corner = corner || read.landing == TexelLanding::Corner;
            }
            if (!count) continue;
            const std::string filter = std::string("\"filter\": \"") + filterName(channel.sampler.filter) + "\"";
            const std::string what = passName(bufferPass(channel.buffer));
            const std::string howMany = count == 1 ? "1 read" : std::to_string(count) + " reads";
            Diagnostic d;
            d.severity = Severity::Warning;
            d.code = Code::ChannelFilter;
            d.file = pass.sourceName;
            d.pass = passName(pass.id);
            d.channel = c;
            d.line = first;
            d.message = corner
                ? "reads " + what + " with texture() on texel corners (" + howMany + ", the first here): with " + filter +
                      " each such read averages the four texels around it; for a pixel-exact shader (a cellular "
                      "automaton, a state buffer) set \"filter\": \"nearest\" in this channel of the manifest, as the "
                      "site's channel settings show"
                : "reads neighbours of " + what + " stepped in uv units (uv + k / resolution; " + howMany +
                      ", the first here) and compares values exactly (==): with " + filter +
                      " the step's float rounding mixes a little of the next texel into each value, so exact "
                      "comparisons fail; set \"filter\": \"nearest\" in this channel of the manifest, as the site's "
                      "channel settings show";
            warnings.push_back(std::move(d));
        }
    }
    return warnings;
}

}  // namespace toyhost
