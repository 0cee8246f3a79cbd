// Turns a manifest.json (the project's own format) into a validated ManifestDesc, reading the
// pass sources it names. Every problem is reported at once, each naming the manifest file and
// the exact place (pass, channel, field). No GL needed.
#pragma once

#include <filesystem>
#include <string_view>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

// `target` is a folder holding manifest.json, or the manifest file itself.
Result<ManifestDesc> loadManifest(const std::filesystem::path& target);

// Parses and validates manifest text; relative paths resolve against `manifestPath`'s folder.
Result<ManifestDesc> parseManifest(std::string_view jsonText,
                                   const std::filesystem::path& manifestPath);

}  // namespace toyhost
