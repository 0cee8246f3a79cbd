// Reads shadertoy.com JSON exports (the API form {"Shader": {...}} and the older site form with
// string ids and type/filepath fields) into the same ManifestDesc a manifest gives, so the rest
// of the host cannot tell them apart. No GL needed.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>

#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

// True for a document shaped like an export, even a broken one: an object with "Shader",
// "renderpass", "info" or "ver" and no "passes" (which a manifest has), or an array of such objects
// (the site's own export button writes an array of one; an array of several is an export that
// parseShadertoyExport refuses, naming the shaders).
bool isShadertoyExport(const nlohmann::json& document);

// Converts an export: every pass type (Image, Buffer A-D, Common, Cube A; Sound into
// ManifestDesc::sound) and every input kind. Reads of a buffer or Cube A the shader does not
// define, and inputs of a kind the site does not have, are bound to nothing, each with a line in
// `notices` (an unbound Cube A read stays a samplerCube). Files it names are found beside
// `exportPath`; messages name the export `label` (default: its absolute path), e.g. "code [Image]".
Result<ManifestDesc> parseShadertoyExport(std::string_view jsonText, const std::filesystem::path& exportPath,
                                          std::string label = {});

// Shadertoy's ids for buffer outputs and inputs: 257..260 (API) or "4dXGR8", "XsXGR8",
// "4sXGR8", "XdfGR8" (site form) for Buffer A..D; -1 for anything else.
int bufferIndexFromExportId(const nlohmann::json& id);

}  // namespace toyhost
