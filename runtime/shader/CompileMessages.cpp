#include "shader/CompileMessages.h"

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>

#include "core/Suggest.h"
#include "shader/SourceExcerpt.h"

namespace toyhost {

namespace {

// Names every Shadertoy pass can use besides its own: the uniforms, the entry points and GLSL ES
// 3.00's built-in functions (near misses of these are suggested for undeclared names).
const std::vector<std::string>& knownNames() {
    static const std::vector<std::string> names{
        "iResolution", "iTime", "iTimeDelta", "iFrameRate", "iFrame", "iMouse", "iDate", "iSampleRate",
        "iChannelTime", "iChannelResolution", "iChannel0", "iChannel1", "iChannel2", "iChannel3", "mainImage",
        "mainSound", "mainCubemap", "gl_FragCoord", "radians", "degrees", "sin", "cos", "tan", "asin", "acos",
        "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "pow", "exp", "log", "exp2", "log2", "sqrt",
        "inversesqrt", "abs", "sign", "floor", "trunc", "round", "roundEven", "ceil", "fract", "mod", "modf", "min",
        "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "floatBitsToInt", "floatBitsToUint",
        "intBitsToFloat", "uintBitsToFloat", "packHalf2x16", "unpackHalf2x16", "length", "distance", "dot",
        "cross", "normalize", "faceforward", "reflect", "refract", "matrixCompMult", "outerProduct", "transpose",
        "determinant", "inverse", "lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual", "equal",
        "notEqual", "any", "all", "not", "textureSize", "texture", "textureProj", "textureLod", "textureOffset",
        "texelFetch", "texelFetchOffset", "textureGrad", "textureLodOffset", "textureProjLod", "textureGradOffset",
        "dFdx", "dFdy", "fwidth"};
    return names;
}

// GLSL ES 1.00 names (WebGL 1, old tutorials) that GLSL ES 3.00, which Shadertoy uses, renamed.
std::optional<std::string> renamedFunction(const std::string& name) {
    static const std::map<std::string, std::string> renamed{
        {"texture2D", "texture"}, {"textureCube", "texture"}, {"texture3D", "texture"},
        {"texture2DLod", "textureLod"}, {"textureCubeLod", "textureLod"}, {"texture2DLodEXT", "textureLod"},
        {"textureCubeLodEXT", "textureLod"}, {"texture2DProj", "textureProj"}, {"texture2DGradEXT", "textureGrad"}};
    auto it = renamed.find(name);
    if (it == renamed.end()) return std::nullopt;
    return it->second;
}

bool isError(const Diagnostic& d) { return d.severity == Severity::Error; }

// An error that only repeats an earlier one: an expression whose type is already `error' (the
// undeclared name it uses was reported), or the token the lexer made of a reserved word.
bool isFollowOn(const Diagnostic& d) {
    static const std::regex followOn(R"((\(|, )error(,|\))|\btype error\b|ERROR_TOK)");
    return isError(d) && std::regex_search(d.message, followOn);
}

// Errors Mesa adds on the line of an undeclared name or unknown function, about the expression
// that used it.
bool isCascade(const Diagnostic& d) {
    static const std::regex operandType(R"(^(LHS|RHS|operands?)\b.* must be )");
    return isError(d) && (std::regex_search(d.message, operandType) || d.message == "type mismatch" ||
                          d.message.find("from a non-numeric data type") != std::string::npos);
}

bool isUnknownName(const Diagnostic& d) {
    return isError(d) && (d.message.find("undeclared") != std::string::npos ||
                          d.message.rfind("no function with name", 0) == 0);
}

// Errors that make the type of an expression unknown: what Mesa then says about the expression
// holding it (a constructor "from a non-numeric data type", a "type mismatch") only follows.
bool isCascadeRoot(const Diagnostic& d) {
    return isUnknownName(d) || (isError(d) && d.message.rfind("invalid swizzle", 0) == 0);
}

// The entry point a pass defines and how Shadertoy declares it (ShaderAssembly calls it so).
struct EntryPoint {
    const char* name;
    const char* declaration;
};
EntryPoint entryPointOf(std::string_view pass) {
    if (pass == "Sound") return {"mainSound", "vec2 mainSound(int samp, float time)"};
    if (pass.rfind("Cube", 0) == 0)
        return {"mainCubemap",
                "void mainCubemap(out vec4 fragColor, in vec2 fragCoord, in vec3 rayOri, in vec3 rayDir)"};
    return {"mainImage", "void mainImage(out vec4 fragColor, in vec2 fragCoord)"};
}

// A #define of the user's text: where it is and the names its body uses.
struct MacroDefinition {
    int line = 0;
    std::vector<std::string> uses;
};

std::map<std::string, MacroDefinition> macroDefinitions(const SourceView& view) {
    static const std::regex define(R"(^\s*#\s*define\s+([A-Za-z_]\w*)(\([^)]*\))?(.*)$)");
    static const std::regex word(R"([A-Za-z_]\w*)");
    std::map<std::string, MacroDefinition> macros;
    for (int n = 1; n <= view.lineCount(); ++n) {
        if (view.directiveOf(n) != "#define") continue;
        std::string text(view.line(n));
        // A body continued with '\' goes on over the next lines.
        for (int next = n + 1; !text.empty() && text.back() == '\\' && next <= view.lineCount(); ++next)
            text.back() = ' ', text.append(view.line(next));
        std::smatch m;
        if (!std::regex_match(text, m, define)) continue;
        MacroDefinition& macro = macros[m[1].str()];
        macro.line = n;
        const std::string body = m[3].str();
        for (std::sregex_iterator it(body.begin(), body.end(), word), end; it != end; ++it) macro.uses.push_back(it->str());
    }
    return macros;
}

// The chain of macros through which `name`'s body comes back to `name` ("LOOP_A" alone for
// `#define LOOP_A LOOP_A`), or empty when it does not. The preprocessor leaves a macro's own name
// in its expansion as it is, so the compiler then meets that name as an undeclared one.
std::vector<std::string> selfReference(const std::map<std::string, MacroDefinition>& macros, const std::string& name) {
    std::vector<std::string> chain{name};
    std::set<std::string> seen{name};
    std::function<bool(const std::string&)> reaches = [&](const std::string& from) {
        auto it = macros.find(from);
        if (it == macros.end()) return false;
        for (const std::string& used : it->second.uses) {
            if (used == name) return true;
            if (!macros.count(used) || !seen.insert(used).second) continue;
            chain.push_back(used);
            if (reaches(used)) return true;
            chain.pop_back();
        }
        return false;
    };
    return reaches(name) ? chain : std::vector<std::string>{};
}

// Macro names are written in capitals by convention and variables are not: a near miss is only
// looked for among names of its own style (and the built-in names), so that a misspelt macro is
// never offered a local variable that only matches with case ignored, nor the reverse.
bool capitalsOnly(std::string_view name) {
    bool letter = false;
    for (char c : name) {
        if (c >= 'a' && c <= 'z') return false;
        letter = letter || (c >= 'A' && c <= 'Z');
    }
    return letter;
}

// Mesa lists each candidate of a failed overload as a message of its own after "candidates are:".
// They are folded into that message: the candidate closest to the call's argument types, and how
// many more there are.
void foldCandidates(std::vector<Diagnostic>& problems) {
    static const std::regex candidate(R"(^\s*\w+ \w+\(([^()]*)\)\s*$)");
    static const std::regex call(R"(call to `\w+\(([^()]*)\)')");
    auto split = [](const std::string& list) {
        std::vector<std::string> parts;
        std::size_t start = 0;
        while (start <= list.size() && !list.empty()) {
            const std::size_t comma = list.find(',', start);
            std::string part = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            part.erase(0, part.find_first_not_of(' '));
            part.erase(part.find_last_not_of(' ') + 1);
            parts.push_back(part);
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        return parts;
    };
    for (std::size_t i = 0; i < problems.size(); ++i) {
        Diagnostic& head = problems[i];
        const std::size_t marker = head.message.rfind("candidates are:");
        if (marker == std::string::npos || head.message.find_first_not_of(' ', marker + 15) != std::string::npos) continue;
        std::size_t end = i + 1;
        std::smatch m;
        while (end < problems.size() && problems[end].line == head.line && problems[end].file == head.file &&
               std::regex_match(problems[end].message, m, candidate))
            ++end;
        const std::size_t count = end - i - 1;
        if (count == 0) continue;
        std::vector<std::string> arguments;
        if (std::regex_search(head.message, m, call)) arguments = split(m[1].str());
        std::size_t best = i + 1;
        int bestScore = -1;
        for (std::size_t c = i + 1; c < end; ++c) {
            std::regex_match(problems[c].message, m, candidate);
            const std::vector<std::string> parameters = split(m[1].str());
            int score = parameters.size() == arguments.size() ? 100 : 0;
            for (std::size_t p = 0; p < std::min(parameters.size(), arguments.size()); ++p)
                score += parameters[p] == arguments[p];
            if (score > bestScore) bestScore = score, best = c;
        }
        std::string closest = problems[best].message;
        closest.erase(0, closest.find_first_not_of(' '));
        head.message = head.message.substr(0, marker) + "candidates are: " + closest +
                       (count > 1 ? " ... " + std::to_string(count - 1) + (count == 2 ? " more candidate" : " more candidates")
                                  : "");
        problems.erase(problems.begin() + static_cast<std::ptrdiff_t>(i) + 1, problems.begin() + static_cast<std::ptrdiff_t>(end));
    }
}

// The name a message is about: Mesa quotes it as `name' or 'name'.
std::string quotedName(const std::string& message) {
    static const std::regex quoted(R"([`']([A-Za-z_][A-Za-z0-9_]*)')");
    std::smatch m;
    return std::regex_search(message, m, quoted) ? m[1].str() : std::string();
}

bool endsLikeAStatement(std::string_view line, int lastColumn) {
    if (lastColumn < 1) return false;
    const char c = line[static_cast<std::size_t>(lastColumn - 1)];
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ')' ||
           c == ']' || c == '.';
}

// One problem about a user's file, rewritten: where it is, what to say, how wide the caret.
struct Explained {
    SourcePosition at;
    std::string message;
    int width = 1;
};

class Explainer {
public:
    Explainer(const SourceView& view, const std::vector<std::string>& names,
              const std::map<std::string, MacroDefinition>& macros, std::string pass)
        : view_(view), names_(names), macros_(macros), pass_(std::move(pass)) {}

    Explained explain(const Diagnostic& d) const {
        Explained e{d.column > 0 ? view_.fromCompilerPosition(d.line, d.column) : SourcePosition{d.line, 0}, d.message};
        if (e.at.column == 0) e.at.column = view_.firstCodeColumn(e.at.line);
        // A message about a name: the caret goes under that name (Mesa's column can be off after a
        // macro that expands to text of another length).
        const std::string name = quotedName(d.message);
        if (!name.empty()) {
            if (const int column = view_.nearestWord(e.at.line, name, e.at.column); column != 0) {
                e.at.column = column;
                e.width = static_cast<int>(name.size());
            }
        }
        if (isError(d)) {
            static const std::regex syntax(R"(^syntax error, unexpected (.+?)(, expecting (.+))?$)");
            std::smatch m;
            if (std::regex_match(d.message, m, syntax)) explainSyntax(m[1].str(), m[3].str(), d.message, e);
            else explainSemantic(name, d.message, e);
        }
        return e;
    }

private:
    void explainSyntax(const std::string& unexpected, const std::string& expecting, const std::string& original,
                       Explained& e) const {
        const std::string token = view_.tokenAt(e.at.line, e.at.column);
        if (unexpected == "end of file" || unexpected == "$end") {
            // The file ends inside a block: the '{' that is never closed is where to look.
            e.message = "the code ends inside a block: a '}' is missing";
            if (const int open = view_.unclosedBraceLine(); open != 0) {
                e.message += " (the block opened on line " + std::to_string(open) + " is never closed)";
                const std::string_view text = view_.line(open);
                for (int c = static_cast<int>(text.size()); c >= 1; --c)
                    if (text[c - 1] == '{' && !view_.inComment(open, c)) {
                        e.at = {open, c};
                        break;
                    }
            }
            e.message += " (" + original + ")";
            return;
        }
        if (unexpected == "'}'" && expecting.find("end of file") != std::string::npos) {
            e.message = "one '}' too many: every block is already closed here (" + original + ")";
            return;
        }
        // A ';' missing at the end of a line is noticed at the first token of the next code line.
        const int previous = view_.previousCodeLine(e.at.line);
        if (expecting.find("';'") != std::string::npos && e.at.column == view_.firstCodeColumn(e.at.line) &&
            previous != 0 && endsLikeAStatement(view_.line(previous), view_.lastCodeColumn(previous))) {
            const int noticed = e.at.line;
            e.at = {previous, view_.lastCodeColumn(previous) + 1};
            e.width = 1;
            e.message = "';' missing at the end of this line (the compiler noticed at " +
                        (token.empty() ? std::string("the next line") : "`" + token + "' on line " + std::to_string(noticed)) +
                        ": " + original + ")";
            return;
        }
        // A ';' missing before a '}' on the same line ("x = 1.0 }"): noticed at the '}'.
        if (unexpected == "'}'" && expecting.find("';'") != std::string::npos) {
            const std::string_view text = view_.line(e.at.line);
            int before = std::min(e.at.column - 1, static_cast<int>(text.size()));
            while (before >= 1 && (text[before - 1] == ' ' || text[before - 1] == '\t' || view_.inComment(e.at.line, before)))
                --before;
            if (before >= 1 && endsLikeAStatement(text, before)) {
                e.at.column = before + 1;
                e.width = 1;
                e.message = "';' missing here, before the '}' that closes the block (" + original + ")";
                return;
            }
        }
        if ((unexpected == "';'" || unexpected == "'{'") && expecting.find("')'") != std::string::npos) {
            e.message = "a ')' is missing before this " + unexpected + " (" + original + ")";
            return;
        }
        // A function definition read as a statement: the block above it was never closed.
        if (unexpected == "'{'") {
            if (const int open = view_.unclosedBraceLine(); open != 0 && open < e.at.line) {
                e.message = "a '}' is missing above: the block opened on line " + std::to_string(open) +
                            " is never closed, so this '{' is read inside it (" + original + ")";
                return;
            }
        }
        if (unexpected == "')'") {
            e.message = "one ')' too many here, or a '(' missing before it (" + original + ")";
            return;
        }
        // Otherwise Mesa's token class (BASIC_TYPE_TOK, FLOATCONSTANT, ...) becomes the token itself.
        if (!token.empty() && unexpected.front() != '\'') {
            e.message = "syntax error, unexpected `" + token + "' (" + unexpected + ")" +
                        (expecting.empty() ? "" : ", expecting " + expecting);
            e.width = static_cast<int>(token.size());
        }
    }

    void explainSemantic(const std::string& name, const std::string& original, Explained& e) const {
        static const std::regex intToFloat(
            R"(of type (int|uint|[iu]vec[234]) cannot be assigned to variable of type (float|vec[234]))");
        if (original.find("undeclared") != std::string::npos && !name.empty()) {
            if (name == "iGlobalTime") e.message += " (Shadertoy renamed iGlobalTime to iTime)";
            else if (name == "gl_FragColor")
                e.message += " (a Shadertoy pass writes its colour to mainImage's first parameter, out vec4 fragColor)";
            else if (macros_.count(name)) e.message += macroExplanation(name, e.at.line);
            else if ((name == "fragColor" || name == "fragCoord") && !view_.functionDefinitionLines("main").empty())
                e.message += " (" + name + " is a parameter of mainImage, which this pass does not define)";
            else e.message += suggestion(name);
        } else if (original.rfind("no function with name", 0) == 0 && !name.empty()) {
            const std::vector<int> defined = view_.functionDefinitionLines(name);
            if (!defined.empty() && defined.front() > e.at.line)
                e.message += " (" + name + " is defined on line " + std::to_string(defined.front()) +
                             ", below this call: GLSL needs a function defined or declared above its first use)";
            else if (std::optional<std::string> now = renamedFunction(name))
                e.message += " (GLSL ES 3.00, which Shadertoy uses, calls it " + *now + ")";
            else e.message += suggestion(name);
        } else if (name == "main" && original.find("redefined") != std::string::npos) {
            // A glslsandbox or plain-GLSL shader: the host's main() calls the pass's entry point.
            const EntryPoint entry = entryPointOf(pass_);
            e.message = "a Shadertoy pass defines " + std::string(entry.name) + ", not main: the host's own main() calls " +
                        entry.name + "; write `" + entry.declaration + "' instead of `void main()'" +
                        (std::string_view(entry.name) == "mainImage"
                             ? ", assign the colour to fragColor instead of gl_FragColor and use fragCoord for "
                               "gl_FragCoord.xy (glslsandbox's time, resolution and mouse are iTime, "
                               "iResolution.xy and iMouse)"
                             : "") +
                        " (" + original + ")";
        } else if (original.rfind("illegal use of reserved word", 0) == 0 && !name.empty()) {
            e.message += " (`" + name + "' is reserved in GLSL ES 3.00: give it another name)";
        } else if (std::regex_search(original, intToFloat)) {
            e.message += " (GLSL ES 3.00 never turns an int into a float: write 1.0 rather than 1, or float(n))";
        } else if (original == "could not implicitly convert operands to arithmetic operator") {
            e.message += " (int and float do not mix in GLSL ES 3.00: write 2.0 rather than 2, or convert with float(n))";
        }
    }

    std::string suggestion(const std::string& name) const {
        std::vector<std::string> sameStyle;
        for (const std::string& candidate : names_)
            if (capitalsOnly(candidate) == capitalsOnly(name)) sameStyle.push_back(candidate);
        std::optional<std::string> match = closestMatch(name, sameStyle);
        return match ? " (did you mean `" + *match + "'?)" : "";
    }

    // An undeclared name that is a macro of the user's: one that refers to itself, or one used
    // above its #define.
    std::string macroExplanation(const std::string& name, int usedOn) const {
        const MacroDefinition& macro = macros_.at(name);
        const std::vector<std::string> chain = selfReference(macros_, name);
        if (!chain.empty()) {
            std::string through;
            for (std::size_t i = 1; i < chain.size(); ++i) through += (i > 1 ? ", then `" : " through `") + chain[i] + "'";
            return " (the macro `" + name + "' defined on line " + std::to_string(macro.line) + " refers to itself" +
                   through + ": the preprocessor leaves a macro's own name in its expansion, so the compiler meets `" +
                   name + "' as a name nothing declares)";
        }
        if (macro.line > usedOn)
            return " (`" + name + "' is a macro defined on line " + std::to_string(macro.line) +
                   ", below this use: a #define applies only to the lines after it)";
        return "";
    }

    const SourceView& view_;
    const std::vector<std::string>& names_;
    const std::map<std::string, MacroDefinition>& macros_;
    std::string pass_;
};

// The linker's "unresolved reference to function `mainImage'": the pass does not define its entry
// point as Shadertoy declares it. Said with the declaration expected and, when the pass defines
// a near miss (a function of that name with other parameters, `mainimage`, `mainImg`), where.
void explainMissingEntryPoint(Diagnostic& d, const std::vector<CompileSource>& sources,
                              const std::vector<std::unique_ptr<SourceView>>& views) {
    const EntryPoint entry = entryPointOf(d.pass);
    if (d.message.find("unresolved reference to function `" + std::string(entry.name) + "'") == std::string::npos) return;
    std::string original = d.message;
    if (original.rfind("error: ", 0) == 0) original.erase(0, 7);
    d.message = "no `" + std::string(entry.declaration) + "' in this pass";
    for (std::size_t s = 0; s < sources.size(); ++s) {
        const SourceView& view = *views[s];
        if (view.hasLineDirective()) continue;
        std::vector<std::string> defined;
        for (const std::string& word : view.identifiers())
            if (!view.functionDefinitionLines(word).empty()) defined.push_back(word);
        std::string nearMiss;
        if (std::find(defined.begin(), defined.end(), entry.name) != defined.end()) nearMiss = entry.name;
        else if (std::optional<std::string> match = closestMatch(entry.name, defined)) nearMiss = *match;
        if (nearMiss.empty()) continue;
        const int line = view.functionDefinitionLines(nearMiss).front();
        d.file = sources[s].file;
        d.line = line;
        d.column = std::max(1, view.nearestWord(line, nearMiss, 1));
        d.message += nearMiss == entry.name
                         ? ": the `" + nearMiss + "' defined here has other parameters"
                         : ": did you mean this `" + nearMiss + "'? (names are case-sensitive)";
        d.excerpt = formatExcerpt(view.line(line), line, d.column, static_cast<int>(nearMiss.size()));
        break;
    }
    d.message += " (link: " + original + ")";
}

}  // namespace

std::vector<Diagnostic> explainCompileProblems(std::vector<Diagnostic> problems, const std::vector<CompileSource>& sources) {
    foldCandidates(problems);
    // What only follows from another error goes; the first error comes first, warnings after the
    // errors (a failed initialiser also makes its variable "used uninitialized").
    const bool anyRootError = std::any_of(problems.begin(), problems.end(),
                                          [](const Diagnostic& d) { return isError(d) && !isFollowOn(d); });
    if (anyRootError) {
        std::vector<Diagnostic> kept;
        for (const Diagnostic& d : problems) {
            // The expression Mesa complains about starts on its line and holds the unknown name,
            // on that line or a few below (an expression written over several lines).
            const bool afterUnknownName = isCascade(d) && std::any_of(kept.begin(), kept.end(), [&](const Diagnostic& k) {
                return isCascadeRoot(k) && k.file == d.file && k.line >= d.line && k.line - d.line <= 10;
            });
            if (isFollowOn(d) || afterUnknownName) continue;
            if (!isError(d) && d.message.find("used uninitialized") != std::string::npos) continue;
            kept.push_back(d);
        }
        problems = std::move(kept);
    }
    std::stable_partition(problems.begin(), problems.end(), isError);

    // Names to suggest for a near miss: the known ones and every word of the user's code, except
    // those the compiler reports as undeclared themselves.
    std::set<std::string> unknown;
    for (const Diagnostic& d : problems)
        if (isUnknownName(d)) unknown.insert(quotedName(d.message));
    std::vector<std::unique_ptr<SourceView>> views;
    std::vector<std::string> names = knownNames();
    for (const CompileSource& source : sources) {
        views.push_back(std::make_unique<SourceView>(source.code));
        for (std::string& word : views.back()->identifiers())
            if (!unknown.count(word)) names.push_back(std::move(word));
    }
    std::vector<std::map<std::string, MacroDefinition>> macros;
    for (const std::unique_ptr<SourceView>& view : views) macros.push_back(macroDefinitions(*view));
    for (Diagnostic& d : problems) {
        if (d.line <= 0) {
            explainMissingEntryPoint(d, sources, views);
            continue;
        }
        for (std::size_t s = 0; s < sources.size(); ++s) {
            const SourceView& view = *views[s];
            if (sources[s].file != d.file || view.hasLineDirective() || d.line > view.lineCount()) continue;
            const Explained e = Explainer(view, names, macros[s], d.pass).explain(d);
            d.line = e.at.line;
            d.column = e.at.column;
            d.message = e.message;
            d.excerpt = formatExcerpt(view.line(d.line), d.line, d.column, e.width);
            break;
        }
    }
    return problems;
}

}  // namespace toyhost
