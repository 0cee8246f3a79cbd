// Starter: the folder `toyhost new` writes, a shadertoy that runs at once: a manifest, pass files
// holding the site's default code (or a small feedback example for buffers) and a README stub.
// Plain data and file writing; no GL needed.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

struct StarterLayout {
    bool common = false;
    bool buffers[kBufferCount] = {false, false, false, false};
};

// "image" (Image only), "buffer"/"buffers" (Buffer A feeding itself and Image: the usual
// two-pass start) or a comma list of "common", "a".."d" (or "Buffer A"..), "image"; Image is
// always part of it. Errors name the word that is not a pass.
Result<StarterLayout> parseStarterLayout(std::string_view text);

// The starter as a manifest (name from the folder's name; pass paths inside `dir`) with its code.
ManifestDesc starterManifest(const std::filesystem::path& dir, const StarterLayout& layout);

// Writes `dir` (created when missing): manifest.json, the pass files and README.md. Refuses a
// folder that already holds a manifest.json unless `overwrite`.
Status writeStarter(const std::filesystem::path& dir, const StarterLayout& layout, bool overwrite);

}  // namespace toyhost
