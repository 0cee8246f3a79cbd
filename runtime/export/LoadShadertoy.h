// The one entry point for "what the user pointed at": a folder with manifest.json, a manifest
// file, or a Shadertoy JSON export (API or site form). No GL needed.
#pragma once

#include <filesystem>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

Result<ManifestDesc> loadShadertoy(const std::filesystem::path& target);

}  // namespace toyhost
