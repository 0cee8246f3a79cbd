#include "export/LoadShadertoy.h"

#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "export/ShadertoyExport.h"
#include "manifest/ManifestLoader.h"

namespace toyhost {
namespace fs = std::filesystem;

Result<ManifestDesc> loadShadertoy(const fs::path& target) {
    std::error_code ec;
    if (fs::is_directory(target, ec)) return loadManifest(target);
    Result<std::string> text = readTextFile(target);
    if (!text) return text.error();
    // Exports and manifests are both JSON; malformed JSON is reported by the manifest parser.
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
    } catch (const nlohmann::json::exception&) {
        document = nlohmann::json(nlohmann::json::value_t::discarded);  // reported by the parser below
    }
    if (!document.is_discarded() && isShadertoyExport(document)) return parseShadertoyExport(*text, target);
    return parseManifest(*text, target);
}

}  // namespace toyhost
