// CompileMessages: what a user reads when a pass does not compile. From the compiler's messages
// (parseCompilerLog) and the user's own files it makes: positions in the user's text (Mesa counts
// columns after collapsing whitespace), an excerpt with a caret under each problem, plain words for
// the commonest parser errors (a missing ';' is named on the line it is missing from, not on the
// next line where the parser noticed), the errors before the warnings, errors that only follow from
// an earlier one left out, and overload candidate lists folded to the closest candidate. The
// compiler's own wording stays in each message, so that it can still be searched for. Pure text
// work; no GL needed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/Diagnostic.h"

namespace toyhost {

// One file the compiled text came from, as the compiler's diagnostics name it.
struct CompileSource {
    std::string file;       // Diagnostic::file of its problems (CompilerLogNames::passFile / commonFile)
    std::string_view code;  // the text as the user wrote it
};

// `problems` (one pass's compile messages, in the compiler's order) made readable, as described
// above. Problems about a file not in `sources` (the generated header), and files with a #line
// directive of the user's own (their line numbers are the user's to choose), keep their positions
// and get no excerpt.
std::vector<Diagnostic> explainCompileProblems(std::vector<Diagnostic> problems, const std::vector<CompileSource>& sources);

}  // namespace toyhost
