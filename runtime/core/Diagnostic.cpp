#include "core/Diagnostic.h"

namespace toyhost {

const char* severityName(Severity severity) {
    switch (severity) {
        case Severity::Error: return "error";
        case Severity::Warning: return "warning";
        case Severity::Notice: return "notice";
    }
    return "error";
}

std::string formatDiagnostic(const Diagnostic& d) {
    std::string out;
    if (!d.file.empty()) {
        out += d.file;
        if (d.line > 0) {
            out += ':' + std::to_string(d.line);
            if (d.column > 0) out += ':' + std::to_string(d.column);
        }
        out += ": ";
    }
    out += severityName(d.severity);
    out += ": ";
    // The pass (and channel), unless the JSON field already names it (passes."Image"...).
    if (!d.pass.empty() && d.field.find("\"" + d.pass + "\"") == std::string::npos) {
        out += d.pass;
        if (d.channel >= 0) out += " / iChannel" + std::to_string(d.channel);
        out += ": ";
    }
    if (!d.field.empty()) out += d.field + ": ";
    out += d.message;
    if (d.code != Code::Unclassified) {
        out += " [";
        out += codeName(d.code);
        out += "]";
    }
    return out;
}

std::string formatDiagnosticWithExcerpt(const Diagnostic& d, const std::string& prefix) {
    std::string out = prefix + formatDiagnostic(d);
    if (!d.excerpt.empty()) {
        out += '\n';
        out += d.excerpt;
        if (out.back() == '\n') out.pop_back();
    }
    return out;
}

std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, const std::string& prefix,
                              std::size_t limit) {
    std::string out;
    const std::size_t shown = diagnostics.size() > limit ? limit : diagnostics.size();
    for (std::size_t i = 0; i < shown; ++i) {
        if (i) out += '\n';
        out += formatDiagnosticWithExcerpt(diagnostics[i], prefix);
    }
    if (shown < diagnostics.size())
        out += '\n' + prefix + "... and " + std::to_string(diagnostics.size() - shown) + " more";
    return out;
}

}  // namespace toyhost
