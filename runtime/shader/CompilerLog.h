// CompilerLog: turns a GLSL compiler's info log into Diagnostics that name the user's file, pass,
// line and column (shader/ShaderAssembly.h numbers the generated text so that the line alone
// says whether a message is about the header, Common or the pass). Understands Mesa's
// "S:L(C): error: msg", ANGLE/glslang's "ERROR: S:L: msg" and NVIDIA's "S(L) : error C...: msg".
// Pure text work; no GL needed.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/Diagnostic.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

struct CompilerLogNames {
    std::string pass;        // "Buffer A": every diagnostic's pass
    std::string passFile;    // how messages name the pass's file ("/toy/image.glsl", "x.json [Image]")
    std::string commonFile;  // ... and Common's
};

// One diagnostic per message line (code Code::ShaderCompile; warnings keep Severity::Warning).
// Lines the parser does not recognise are kept as messages about the pass without a line.
std::vector<Diagnostic> parseCompilerLog(std::string_view log, const CompilerLogNames& names);

// Appends one pass's compile problems to `all`. A problem in Common is compiled into every pass
// and would be reported once per pass: it is named as Common's and kept once.
void mergeCompileProblems(std::vector<Diagnostic>& all, const std::vector<Diagnostic>& more,
                          const ManifestDesc& manifest);

}  // namespace toyhost
