// libFuzzer target: manifest.json text through toyhost::parseManifest (runtime/manifest/), with a
// fixed manifest path in a temp folder that holds a few tiny pass files, so that "source",
// "common" and "texture" references resolve sometimes. Errors are formatted too (Error::text()).
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "manifest/ManifestLoader.h"

namespace fs = std::filesystem;

namespace {

fs::path gManifest;

void removeFolder() {
    std::error_code ec;
    if (!gManifest.empty()) fs::remove_all(gManifest.parent_path(), ec);
}

void write(const fs::path& file, std::string_view text) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string dir = (fs::temp_directory_path() / "toyhost-fuzz-manifest-XXXXXX").string();
    if (!::mkdtemp(dir.data())) std::abort();
    const fs::path folder(dir);
    const char* code = "void mainImage(out vec4 c, in vec2 f) { c = vec4(1.0); }\n";
    for (const char* name : {"image.glsl", "buffer_a.glsl", "buffer_b.glsl", "common.glsl"})
        write(folder / name, code);
    write(folder / "tile.png", "\x89PNG\r\n\x1a\n");  // named by "texture"; the loader does not decode it
    fs::create_directory(folder / "sub");
    write(folder / "sub" / "image.glsl", code);
    gManifest = folder / "manifest.json";  // never written: only its folder matters
    std::atexit(removeFolder);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    toyhost::Result<toyhost::ManifestDesc> result = toyhost::parseManifest(text, gManifest);
    if (!result) {
        volatile std::size_t length = result.error().text().size();
        (void)length;
    }
    return 0;
}
