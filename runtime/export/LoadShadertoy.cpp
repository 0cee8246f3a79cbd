#include "export/LoadShadertoy.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "export/ShadertoyExport.h"
#include "manifest/CodeShadertoy.h"
#include "manifest/ManifestLoader.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

bool sameFile(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::equivalent(a, b, ec);
}

Result<ManifestDesc> loadShaderFile(const fs::path& target) {
    Result<std::string> text = readTextFile(target);
    if (!text) return text.error();
    std::error_code ec;
    const fs::path file = fs::absolute(target, ec).lexically_normal();
    const fs::path folder = file.parent_path();
    const fs::path commonFile = folder / kCommonFileName;
    std::optional<PassCode> common;
    std::vector<Diagnostic> notices;
    auto notice = [&](std::string message) {
        Diagnostic d;
        d.severity = Severity::Notice;
        d.code = Code::ManifestLoneShader;
        d.file = target.string();
        d.message = std::move(message);
        notices.push_back(std::move(d));
    };
    // A common.glsl that is there but cannot be read as one (a link to nothing, a folder) was meant
    // as the Common pass: said, not skipped without a word (issue 46).
    const fs::path shownCommon = target.parent_path() / kCommonFileName;
    if (fs::is_symlink(commonFile, ec) && !fs::exists(commonFile, ec))
        return fileError(shownCommon.string(),
                         "is a symbolic link to " + fs::read_symlink(commonFile, ec).string() +
                             ", which does not exist: the Common pass of " + target.string() +
                             " cannot be read (remove the link to run without Common)",
                         Code::IoNotFound);
    if (fs::exists(commonFile, ec) && !fs::is_regular_file(commonFile, ec))
        return fileError(shownCommon.string(),
                         "is not a regular file: the Common pass of " + target.string() + " cannot be read",
                         Code::IoNotAFile);
    if (fs::is_regular_file(commonFile, ec) && !sameFile(commonFile, file)) {
        Result<std::string> code = readTextFile(commonFile);
        if (!code) return code.error();
        common = PassCode{std::move(*code), commonFile, shownCommon.string()};
        notice("runs as an Image-only shadertoy with " + shownCommon.string() + " (next to it) as its Common pass");
    } else {
        notice("runs as an Image-only shadertoy (no channels bound)");
    }
    if (fs::exists(folder / "manifest.json", ec))
        notice("its folder has a manifest.json: give the folder to run the whole shadertoy (its buffers and channels)");
    ManifestDesc desc = imageOnlyShadertoy(target.stem().string(), file, PassCode{std::move(*text), file, target.string()},
                                           std::move(common));
    desc.notices = std::move(notices);
    return desc;
}

}  // namespace

bool isShaderFileName(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".glsl" || extension == ".frag";
}

Result<ManifestDesc> loadShadertoy(const fs::path& target) {
    std::error_code ec;
    if (fs::is_directory(target, ec)) return loadManifest(target);
    if (isShaderFileName(target)) return loadShaderFile(target);
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
