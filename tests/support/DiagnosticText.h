// Diagnostics as plain text for tests that check the place and the message but not the short
// code or the severity word: "FILE:LINE:COL: PASS / iChannelN: FIELD: MESSAGE" per diagnostic,
// one per line (formatDiagnostic's order without "error: " and " [code]"). No GL needed.
#pragma once

#include <string>

#include "core/Result.h"

namespace toyhost::testing {

inline std::string plainLine(const Diagnostic& d) {
    std::string out;
    if (!d.file.empty()) {
        out += d.file;
        if (d.line > 0) {
            out += ':' + std::to_string(d.line);
            if (d.column > 0) out += ':' + std::to_string(d.column);
        }
        out += ": ";
    }
    if (!d.pass.empty() && d.field.find("\"" + d.pass + "\"") == std::string::npos) {
        out += d.pass;
        if (d.channel >= 0) out += " / iChannel" + std::to_string(d.channel);
        out += ": ";
    }
    if (!d.field.empty()) out += d.field + ": ";
    return out + d.message;
}

inline std::string plainText(const Error& error) {
    std::string out;
    for (const Diagnostic& d : error.diagnostics) out += (out.empty() ? "" : "\n") + plainLine(d);
    return out;
}

}  // namespace toyhost::testing
