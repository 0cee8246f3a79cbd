// The one entry point for "what the user pointed at": a folder with manifest.json, a manifest
// file, a Shadertoy JSON export (API or site form), or a lone shader file (.glsl, .frag: an
// Image-only shadertoy, with the common.glsl next to it as Common when there is one). No GL needed.
#pragma once

#include <filesystem>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

Result<ManifestDesc> loadShadertoy(const std::filesystem::path& target);

// The name of a lone shader file (.glsl or .frag, any case).
bool isShaderFileName(const std::filesystem::path& path);

// The Common file a lone shader file takes from its folder.
inline constexpr const char* kCommonFileName = "common.glsl";

}  // namespace toyhost
