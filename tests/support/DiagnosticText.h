// Diagnostics as plain text for tests that check the place and the message but not the short
// code or the severity word: "FILE:LINE:COL: PASS / iChannelN: FIELD: MESSAGE" per diagnostic,
// one per line (formatDiagnostic's order without "error: " and " [code]"). No GL needed.
#pragma once

#include <string>

#include "core/Result.h"

namespace toyhost::testing {

// formatDiagnostic's line without the code and the severity word.
inline std::string plainLine(const Diagnostic& d) {
    std::string out = formatDiagnostic(d);
    if (d.code != Code::Unclassified) out.erase(out.rfind(" ["));  // the code
    const std::string severity = std::string(severityName(d.severity)) + ": ";
    const std::size_t place = d.file.empty() ? 0 : out.find(": ") + 2;  // after FILE[:L[:C]]
    if (out.compare(place, severity.size(), severity) == 0) out.erase(place, severity.size());
    return out;
}

inline std::string plainText(const Error& error) {
    std::string out;
    for (const Diagnostic& d : error.diagnostics) out += (out.empty() ? "" : "\n") + plainLine(d);
    return out;
}

}  // namespace toyhost::testing
