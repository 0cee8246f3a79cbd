// ProblemDigest: a shadertoy's problems as a canvas shows them (the window's overlay): the first
// problem of each pass (of each file, for problems of no pass), its file named relative to the
// shadertoy's folder when it lies inside it, and how many more there are. stderr keeps the whole
// list (formatDiagnostics); a canvas has room for a few lines, and absolute paths wrap every one.
// No GL needed.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "core/Diagnostic.h"

namespace toyhost {

struct ProblemDigest {
    std::vector<Diagnostic> shown;  // the first of each pass (or file), in the order given
    std::size_t more = 0;           // the problems left out
};

ProblemDigest digestProblems(const std::vector<Diagnostic>& problems, const std::filesystem::path& folder);

}  // namespace toyhost
