// CodeShadertoy: the shadertoy a piece of code is on its own: an Image pass without channels,
// with Common when there is one. What a lone .glsl file (export/LoadShadertoy.h) and code read
// from standard input become. Plain data; no GL needed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "manifest/ManifestDesc.h"

namespace toyhost {

struct PassCode {
    std::string code;
    std::filesystem::path source;  // the file holding it (absolute), or a name for code read elsewhere
    std::string sourceName;        // how messages name it: the file as the user gave it, "stdin"
};

// `place` is the shadertoy's manifestPath (absolute): the file, or where the code came from.
ManifestDesc imageOnlyShadertoy(std::string name, std::filesystem::path place, PassCode image,
                                std::optional<PassCode> common = std::nullopt);

}  // namespace toyhost
