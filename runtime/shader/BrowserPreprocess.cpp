#include "shader/BrowserPreprocess.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <span>
#include <vector>

#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/TemporaryFiles.h"
#include "shader/GlslTokens.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

// Lines the C preprocessor must not see (it has no such directives) are replaced by a marker
// and put back afterwards.
const char* kMarker = "toyhost_kept_directive_";

bool isKeptDirective(std::string_view line) {
    std::size_t i = 0;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    if (i >= line.size() || line[i] != '#') return false;
    ++i;
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    for (std::string_view word : {"version", "extension", "pragma"})
        if (line.compare(i, word.size(), word) == 0) return true;
    return false;
}

std::vector<std::string_view> splitLines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        lines.push_back(text.substr(start, end - start));
        if (end == text.size()) break;
        start = end + 1;
    }
    return lines;
}

// `# 12 "<stdin>" 2` -> 12; -1 for any other line.
long lineMarker(std::string_view line) {
    if (line.size() < 3 || line[0] != '#' || line[1] != ' ' || !std::isdigit(static_cast<unsigned char>(line[2])))
        return -1;
    long n = 0;
    std::size_t i = 2;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) n = n * 10 + (line[i++] - '0');
    return (i < line.size() && line[i] == ' ' && i + 1 < line.size() && line[i + 1] == '"') ? n : -1;
}

// The directive word of a preprocessor line (`define` for `  #  define X`) and where its
// operands start; empty for any other line.
std::string_view directiveWord(std::string_view line, std::size_t& after) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string_view::npos || line[i] != '#') return {};
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos) return {};
    std::size_t end = i;
    while (end < line.size() && std::isalpha(static_cast<unsigned char>(line[end]))) ++end;
    after = end;
    return line.substr(i, end - i);
}

// What GLSL ES 3.00's preprocessor refuses (and browsers and Mesa with it) that C's accepts and
// can be seen line by line: token pasting and a macro name with the reserved GL_ prefix. (A
// macro redefined with another body and an undefined name in an evaluated #if depend on which
// groups are skipped: cpp reports those, see below.)
std::optional<std::string> refusedLine(std::string_view line) {
    std::size_t after = 0;
    const std::string_view word = directiveWord(line, after);
    if (word != "define" && word != "undef") return std::nullopt;
    std::string_view rest = line.substr(after);
    if (const std::size_t comment = rest.find("//"); comment != std::string_view::npos) rest = rest.substr(0, comment);
    const std::size_t name = rest.find_first_not_of(" \t");
    if (name != std::string_view::npos && rest.compare(name, 3, "GL_") == 0)
        return "macro names beginning with GL_ are reserved: " + std::string(line);
    if (word == "define" && rest.find("##") != std::string_view::npos)
        return "token pasting (##) is not supported in GLSL ES: " + std::string(line);
    return std::nullopt;
}

// A line of cpp's messages that GLSL ES makes an error although C makes it a warning.
std::optional<std::string> refusedByLog(const std::string& log) {
    for (std::string_view line : splitLines(log))
        if (line.find("warning: \"") != std::string_view::npos && line.find("\" redefined") != std::string_view::npos)
            return std::string(line);
    return std::nullopt;
}

}  // namespace

Result<std::string> preprocessLikeBrowsers(std::string_view shader) {
    if (!findExecutable("cpp"))
        return Error("preprocessing as browsers do needs GCC's cpp, which was not found in PATH", Code::ShaderPreprocess);
    std::vector<std::string> kept;
    std::string input;
    for (std::string_view line : splitLines(shader)) {
        if (std::optional<std::string> refused = refusedLine(line))
            return Error("the shader's preprocessor directives are refused by browsers: " + *refused, Code::ShaderPreprocess);
        if (isKeptDirective(line)) {
            input += std::string(kMarker) + std::to_string(kept.size());
            kept.emplace_back(line);
        } else {
            input += line;
        }
        input += '\n';
    }

    TemporaryFiles temp("cpp", {"glsl", "log"});
    if (!temp.registerAll()) return Error("not preprocessed: toyhost is stopping", Code::Interrupted);
    // GLSL ES 3.00's predefined macros; nothing of C's (-undef), no include paths. An undefined
    // name in an evaluated #if is an error in GLSL ES 3.00 (a 0 in C); warnings (an apostrophe in
    // a skipped block, a redefined macro) only go to the log, read below.
    const std::vector<std::string> args = {"cpp", "-undef", "-nostdinc", "-Werror=undef", "-x", "c", "-U__VERSION__",
                                           "-D__VERSION__=300", "-DGL_ES=1", "-", "-o", temp[0].string()};
    Result<ChildProcess> cpp = ChildProcess::spawn(args, temp[1]);
    if (!cpp) return cpp.error();
    if (Status written = cpp->write(std::as_bytes(std::span(input.data(), input.size()))); !written) {
        (void)cpp->closeAndWait();
        return Error("the preprocessor stopped reading: " + logTail(temp[1]), Code::ShaderPreprocess);
    }
    Result<int> exit = cpp->closeAndWait();
    if (!exit || *exit != 0)
        return Error("the preprocessor rejected the shader: " + logTail(temp[1]), Code::ShaderPreprocess);
    // A macro defined again with another body: an error in GLSL ES, a warning in C.
    if (Result<std::string> log = readTextFile(temp[1], std::size_t(1) << 20); log)
        if (std::optional<std::string> refused = refusedByLog(*log))
            return Error("the preprocessor rejected the shader: " + *refused, Code::ShaderPreprocess);
    Result<std::string> output = readTextFile(temp[0], std::size_t(64) << 20);
    if (!output) return output.error();

    // Line markers become #line; kept directives come back. The first kept line is #version,
    // which must stay the first line: cpp puts its own markers before it.
    std::string expanded;
    bool versionWritten = false;
    for (std::string_view line : splitLines(*output)) {
        if (const long n = lineMarker(line); n >= 0) {
            if (versionWritten) expanded += "#line " + std::to_string(n) + "\n";
            continue;
        }
        if (const std::size_t at = line.find(kMarker); at != std::string_view::npos) {
            const std::size_t index = std::stoul(std::string(line.substr(at + std::string_view(kMarker).size())));
            if (index < kept.size()) {
                expanded += kept[index];
                expanded += '\n';
                versionWritten = true;
                continue;
            }
        }
        if (!versionWritten && line.find_first_not_of(" \t") == std::string_view::npos) continue;
        expanded += line;
        expanded += '\n';
    }
    return expanded;
}

std::string neutraliseUnknownDirectives(std::string_view text) {
    static const std::vector<std::string_view> known = {"define", "undef",  "if",    "ifdef",     "ifndef",  "else", "elif",
                                                        "endif",  "error",  "pragma", "extension", "version", "line"};
    std::string out;
    std::size_t at = 0;
    const std::vector<GlslToken> tokens = tokenizeGlsl(text);
    for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
        const GlslToken& name = tokens[i + 1];
        if (!tokens[i].directiveStart || !name.directive || name.directiveStart || name.kind != GlslToken::Kind::Identifier)
            continue;
        if (std::find(known.begin(), known.end(), name.text) != known.end()) continue;
        out.append(text.substr(at, name.offset - at));
        out += "error invalid directive ";
        at = name.offset;
    }
    out.append(text.substr(at));
    return out;
}

}  // namespace toyhost
