// toyhost/Shadertoy.h (public API, stable): a shadertoy, loaded and validated: a folder holding
// manifest.json, a manifest file, a Shadertoy JSON export file (API or site form), or the text of
// such an export. Loading checks everything that needs no GL (the manifest, every pass's text);
// images and media are read when a Session starts. Cheap to copy (shared, immutable). No GL needed.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <toyhost/Export.h>
#include <toyhost/Result.h>

namespace toyhost {

struct ManifestDesc;     // toyhost's internal description (runtime/manifest)
struct ShadertoyAccess;  // how the runtime reaches it (runtime/api/ShadertoyAccess.h)

class TOYHOST_API Shadertoy {
public:
    // A folder with manifest.json, a manifest file, or an export file. Every problem is reported
    // at once, each naming its file and place.
    static Result<Shadertoy> load(const std::filesystem::path& path);
    // The text of a Shadertoy JSON export ({"Shader": ...} or the site's form). `name` stands for
    // the text in messages; relative files it names (none, for a plain export) resolve against
    // `folder`.
    static Result<Shadertoy> fromExportJson(std::string_view json, std::string name = "export.json",
                                            const std::filesystem::path& folder = {});

    const std::string& name() const;
    // Where it was loaded from (the manifest or export file; the given name for JSON text).
    const std::filesystem::path& path() const;
    // The passes in render order ("Buffer A" .. "Buffer D", "Cube A", "Image"), then "Sound".
    std::vector<std::string> passes() const;
    bool hasSound() const;
    // Things the user should know about the loading (lenient imports), one per diagnostic.
    const std::vector<Diagnostic>& notices() const;

private:
    friend struct ShadertoyAccess;
    explicit Shadertoy(std::shared_ptr<const ManifestDesc> desc) : desc_(std::move(desc)) {}

    std::shared_ptr<const ManifestDesc> desc_;
};

}  // namespace toyhost
