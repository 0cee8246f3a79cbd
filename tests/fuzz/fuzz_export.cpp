// libFuzzer target: Shadertoy JSON export text (API and site form) through
// toyhost::parseShadertoyExport (runtime/export/), formatting the errors and notices it returns.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "export/ShadertoyExport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path kPath = "/exports/fuzz.json";  // only named in messages
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    toyhost::Result<toyhost::ManifestDesc> result = toyhost::parseShadertoyExport(text, kPath);
    volatile std::size_t length = 0;
    if (result) {
        for (const toyhost::Diagnostic& notice : result->notices) length = length + toyhost::formatDiagnostic(notice).size();
    } else {
        length = result.error().text().size();
    }
    (void)length;
    return 0;
}
