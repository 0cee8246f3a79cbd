// libFuzzer target: the image readers toyhost uses on user files: loadImageFile (PNG/JPEG/...,
// libpng and libjpeg-turbo; runtime/image/ImageFile.h) and readExr (OpenEXR; runtime/image/ImageWriters.h). Each
// input is written to one temp file, which both readers then open by path, as toyhost does.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "image/ImageFile.h"
#include "image/ImageWriters.h"

namespace fs = std::filesystem;

namespace {

fs::path gFile;

void removeFolder() {
    std::error_code ec;
    if (!gFile.empty()) fs::remove_all(gFile.parent_path(), ec);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string dir = (fs::temp_directory_path() / "toyhost-fuzz-image-XXXXXX").string();
    if (!::mkdtemp(dir.data())) std::abort();
    gFile = fs::path(dir) / "input";
    std::atexit(removeFolder);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::FILE* file = std::fopen(gFile.c_str(), "wb");
    if (!file) std::abort();
    if (size && std::fwrite(data, 1, size, file) != size) std::abort();
    if (std::fclose(file) != 0) std::abort();

    volatile std::size_t sink = 0;
    if (toyhost::Result<toyhost::Image8> image = toyhost::loadImageFile(gFile))
        sink = sink + image->rgba.size() + std::size_t(image->width) + std::size_t(image->height);
    else
        sink = sink + image.error().text().size();
    if (toyhost::Result<toyhost::ImageF32> image = toyhost::readExr(gFile))
        sink = sink + image->rgba.size() + std::size_t(image->width) + std::size_t(image->height);
    else
        sink = sink + image.error().text().size();
    (void)sink;
    return 0;
}
