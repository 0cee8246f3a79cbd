// Reload: what a hot reload did (ReloadOutcome) and the one notice that says so, for the window's
// live reload, `--watch` rounds and the library's Session::reload. Plain data; no GL needed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"

namespace toyhost {

struct ReloadOutcome {
    std::vector<std::filesystem::path> changed;  // the files that changed
    bool applied = false;                        // new code or structure runs now
    bool structureChanged = false;
    std::vector<std::string> recompiled;         // passes whose new code runs
    // Empty when everything the files say runs now; else what does not (a pass that does not
    // compile keeps its last good program; a manifest that does not load keeps the old one).
    std::vector<Diagnostic> problems;
};

// "buffer_a.glsl changed: recompiled Buffer A" (or what was not applied, and why). A live reload
// (a window, the library's Session::reload) goes on from the current frame, so buffers that still
// exist keep their content. `rerunFrames` set: a --watch round that renders that many frames again
// from frame 0 (every buffer starts anew), said in the same line; one that is not applied writes no
// frames, which the line says too.
Diagnostic describeReload(const ReloadOutcome& outcome, std::optional<int> rerunFrames = std::nullopt);

}  // namespace toyhost
