#include "shader/CompilerLog.h"

#include <algorithm>

#include <regex>
#include <sstream>

#include "shader/ShaderAssembly.h"

namespace toyhost {

namespace {

// Splits "error: `y' undeclared" into the severity and the rest.
void takeSeverity(std::string text, Diagnostic& d) {
    static const std::regex kind(R"(^\s*(error|warning)\s*(C\d+)?\s*:\s*(.*)$)", std::regex::icase);
    std::smatch m;
    if (std::regex_match(text, m, kind)) {
        d.severity = (m[1].str()[0] == 'w' || m[1].str()[0] == 'W') ? Severity::Warning : Severity::Error;
        d.message = m[3].str();
    } else {
        d.message = std::move(text);
    }
}

}  // namespace

std::vector<Diagnostic> parseCompilerLog(std::string_view log, const CompilerLogNames& names) {
    // Mesa: "0:57(12): error: msg"; glslang/ANGLE: "ERROR: 0:57: msg"; NVIDIA: "0(57) : error C0000: msg".
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(.*)$)");
    static const std::regex angle(R"(^\s*(ERROR|WARNING):\s*(\d+):(\d+):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");

    std::vector<Diagnostic> out;
    std::istringstream lines{std::string(log)};
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        Diagnostic d;
        d.code = Code::ShaderCompile;
        d.pass = names.pass;
        int reported = 0;
        std::smatch m;
        if (std::regex_match(line, m, mesa)) {
            reported = std::stoi(m[2]);
            d.column = std::stoi(m[3]);
            takeSeverity(m[4].str(), d);
        } else if (std::regex_match(line, m, angle)) {
            reported = std::stoi(m[3]);
            d.severity = m[1] == "WARNING" ? Severity::Warning : Severity::Error;
            d.message = m[4].str();
        } else if (std::regex_match(line, m, nvidia)) {
            reported = std::stoi(m[2]);
            takeSeverity(m[3].str(), d);
        } else {
            d.file = names.passFile;
            d.message = line;
            out.push_back(std::move(d));
            continue;
        }
        const SourceLine where = mapGeneratedLine(reported);
        switch (where.part) {
            case SourceLine::Part::Pass: d.file = names.passFile; break;
            case SourceLine::Part::Common: d.file = names.commonFile; break;
            case SourceLine::Part::Header: d.file = "<toyhost header>"; break;
        }
        d.line = where.line;
        out.push_back(std::move(d));
    }
    return out;
}

void mergeCompileProblems(std::vector<Diagnostic>& all, const std::vector<Diagnostic>& more,
                          const ManifestDesc& manifest) {
    for (Diagnostic d : more) {
        if (manifest.commonSource && d.file == manifest.commonName) {
            d.pass = "Common";
            const bool seen = std::any_of(all.begin(), all.end(), [&](const Diagnostic& o) {
                return o.file == d.file && o.line == d.line && o.column == d.column && o.message == d.message &&
                       o.pass == d.pass;
            });
            if (seen) continue;
        }
        all.push_back(std::move(d));
    }
}

}  // namespace toyhost
