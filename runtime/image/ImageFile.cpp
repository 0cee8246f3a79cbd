#include "image/ImageFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <stb_image.h>

#include "core/AtomicFile.h"

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
    if (Status regular = checkRegularFile(path); !regular) return regular.error();

    std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return fileError(path.string(), std::string("cannot open: ") + std::strerror(errno), "io.read");

    // Asking stb for 4 channels gives exactly the WebGL upload: it expands grey to R=G=B and
    // fills a missing alpha with 255, and it never applies gAMA/iCCP/sRGB chunks. The row order
    // is pinned per thread (files are top row first; flipRows below makes it bottom first).
    stbi_set_flip_vertically_on_load_thread(0);
    int width = 0, height = 0, channelsInFile = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load_from_file(file.get(), &width, &height, &channelsInFile, STBI_rgb_alpha));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        return fileError(path.string(), std::string("cannot decode image: ") + (reason ? reason : "unknown error"),
                          "image.decode");
    }

    Image8 image;
    image.width = width;
    image.height = height;
    const std::size_t size = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    image.rgba.assign(pixels.get(), pixels.get() + size);
    flipRows(std::span<std::uint8_t>(image.rgba), width, height);
    return image;
}

}  // namespace toyhost
