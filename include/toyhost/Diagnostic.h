// toyhost/Diagnostic.h (public API, stable): one problem or notice as data: what went wrong, where
// (file, pass, channel, JSON field, line and column) and a short stable code. Every report toyhost
// gives is a list of these, formatted by formatDiagnostic() in one form. No GL needed.
#pragma once

#include <string>
#include <vector>

#include <toyhost/Export.h>
#include <toyhost/DiagnosticCode.h>

namespace toyhost {

enum class Severity { Error, Warning, Notice };

struct Diagnostic {
    Severity severity = Severity::Error;
    // What kind of problem: printed as its short stable text ("manifest.field", "shader.compile"),
    // and its category decides exit codes and control flow (core/DiagnosticCode.h).
    Code code = Code::Unclassified;
    std::string message;  // what is wrong, without the place
    std::string file;     // the file it is about, as the user named it; "" when none
    std::string pass;     // "Buffer A" .. "Image", "Common"; "" when none
    int channel = -1;     // 0..3 when it is about one iChannel
    std::string field;    // JSON path inside `file` (passes."Image".channels.iChannel0); "" when none
    int line = 0;         // 1-based line within `file`; 0 when none
    int column = 0;       // 1-based column; 0 when none
    // The user's source around `line` with a caret under `column`, as lines ready to print after the
    // one-line form ("    4 |     vec3 c = mix(previus, a, 0.5);" then "      |                  ^~~~~~~");
    // "" when there is none (most problems are not about a source line).
    std::string excerpt;
};

TOYHOST_API const char* severityName(Severity severity);  // "error", "warning", "notice"

// One line: "FILE:LINE:COL: SEVERITY: PASS / iChannelN: FIELD: MESSAGE [CODE]", each part left out
// when empty (the pass/channel part also when the JSON field already names the pass).
TOYHOST_API std::string formatDiagnostic(const Diagnostic& diagnostic);

// formatDiagnostic's line, then the diagnostic's excerpt (if any) on the lines below it, without
// a prefix (so that the caret stays under its column).
TOYHOST_API std::string formatDiagnosticWithExcerpt(const Diagnostic& diagnostic, const std::string& prefix = "");

// Every diagnostic formatted, one per line, each line starting with `prefix` and followed by the
// diagnostic's excerpt (formatDiagnosticWithExcerpt); at most `limit` diagnostics, then
// "... and N more".
TOYHOST_API std::string formatDiagnostics(const std::vector<Diagnostic>& diagnostics, const std::string& prefix = "",
                              std::size_t limit = 100);

}  // namespace toyhost
