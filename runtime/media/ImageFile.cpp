#include "media/ImageFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <stb_image.h>

namespace toyhost {
namespace fs = std::filesystem;

namespace {
struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
struct StbFree {
    void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};
}  // namespace

Result<Image8> loadImageFile(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return Error{path.string() + ": file not found"};
    if (fs::is_directory(path, ec)) return Error{path.string() + ": is a folder, not an image"};

    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return Error{path.string() + ": cannot open: " + std::strerror(errno)};

    // Asking stb for 4 channels gives exactly the WebGL upload: it expands grey to R=G=B and
    // fills a missing alpha with 255, and it never applies gAMA/iCCP/sRGB chunks. The row order
    // is pinned per thread so another module's global stb flip setting cannot change it.
    stbi_set_flip_vertically_on_load_thread(0);
    int width = 0, height = 0, channelsInFile = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load_from_file(file.get(), &width, &height, &channelsInFile, STBI_rgb_alpha));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        return Error{path.string() +
                     ": cannot decode image: " + (reason ? reason : "unknown error")};
    }

    Image8 image;
    image.width = width;
    image.height = height;
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    image.rgba.assign(pixels.get(), pixels.get() + size);
    return image;
}

}  // namespace toyhost
