#include <toyhost/Shadertoy.h>

#include "api/ShadertoyAccess.h"
#include "export/LoadShadertoy.h"
#include "export/ShadertoyExport.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

Result<Shadertoy> Shadertoy::load(const std::filesystem::path& path) {
    Result<ManifestDesc> desc = loadShadertoy(path);
    if (!desc) return desc.error();
    return ShadertoyAccess::make(std::move(*desc));
}

Result<Shadertoy> Shadertoy::fromExportJson(std::string_view json, std::string name, const std::filesystem::path& folder) {
    // Text without a folder is named by `name` alone in messages ("code [Image]:1:44"), not glued
    // to the current folder it is not in.
    const std::filesystem::path where = folder.empty() ? std::filesystem::current_path() / name : folder / name;
    Result<ManifestDesc> desc = parseShadertoyExport(json, where, folder.empty() ? name : std::string());
    if (!desc) return desc.error();
    return ShadertoyAccess::make(std::move(*desc));
}

const std::string& Shadertoy::name() const { return desc_->name; }

const std::filesystem::path& Shadertoy::path() const { return desc_->manifestPath; }

std::vector<std::string> Shadertoy::passes() const {
    std::vector<std::string> names;
    for (const PassDesc& pass : desc_->passes) names.emplace_back(passName(pass.id));
    if (desc_->sound) names.emplace_back("Sound");
    return names;
}

bool Shadertoy::hasSound() const { return desc_->sound.has_value(); }

const std::vector<Diagnostic>& Shadertoy::notices() const { return desc_->notices; }

}  // namespace toyhost
