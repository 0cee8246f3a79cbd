// Writes a ManifestDesc out as an editable folder: manifest.json plus one file per pass
// (common.glsl, buffer_a.glsl .. buffer_d.glsl, image.glsl) holding the code byte for byte.
// Used by `toyhost import`. No GL needed.
#pragma once

#include <filesystem>
#include <string>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

// The file name a pass's code gets: "buffer_a.glsl", "image.glsl".
std::string passFileName(PassId id);

// The manifest.json text for `desc`, naming the pass files by passFileName().
std::string manifestJson(const ManifestDesc& desc);

// Writes the folder (created if needed). Refuses to overwrite an existing manifest.json unless
// `overwrite`. Every file is written atomically.
Status writeManifestFolder(const ManifestDesc& desc, const std::filesystem::path& dir, bool overwrite);

}  // namespace toyhost
