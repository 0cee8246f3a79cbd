// ManifestFolder: a fresh folder for one manifest test, holding image.glsl, buffer_a.glsl ..
// buffer_d.glsl and a tex.png (not decoded by the loader), removed afterwards; parses manifest
// text as if it were the folder's manifest.json. For unit tests of the loader; no GL needed.
#pragma once

#include <filesystem>
#include <string>

#include "TestFolder.h"
#include "manifest/ManifestLoader.h"

namespace toyhost::testing {

struct ManifestFolder {
    TestFolder root;
    std::filesystem::path dir = root.path / "toy";
    ManifestFolder() {
        write("image.glsl", "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n");
        for (const char* name : {"buffer_a.glsl", "buffer_b.glsl", "buffer_c.glsl", "buffer_d.glsl"})
            write(name, "void mainImage(out vec4 c, in vec2 f) { c = vec4(0.5); }\n");
        write("tex.png", "not decoded by the loader");
    }
    std::filesystem::path write(const std::string& relative, const std::string& text) const {
        return root.write(std::filesystem::path("toy") / relative, text);
    }
    std::filesystem::path manifest() const { return dir / "manifest.json"; }
    Result<ManifestDesc> parse(const std::string& json) const { return parseManifest(json, manifest()); }
    // The whole message of a manifest with exactly one problem.
    std::string line(const std::string& where, const std::string& what) const {
        return manifest().string() + ": " + (where.empty() ? "" : where + ": ") + what;
    }
};

// Buffer A plus an Image pass whose channels are `channels` (JSON text).
inline std::string imageWithChannels(const std::string& channels) {
    return R"({"passes": {"Buffer A": {"source": "buffer_a.glsl"},
                          "Image": {"source": "image.glsl", "channels": )" +
           channels + "}}}";
}

}  // namespace toyhost::testing
