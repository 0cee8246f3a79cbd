#include "image/ImageFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include <stb_image.h>

#include "core/AtomicFile.h"
#include "image/JpegDecode.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
struct StbFree {
    void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};
}  // namespace

namespace {
// The largest side a texture may have (toyhost's canvas limit, core/Defaults.h).
constexpr int kMaxImageSide = 16384;

// Every PNG chunk fits in the file (stb allocates a chunk's declared length before reading it:
// a 41-byte file can ask for gigabytes, a fuzz finding).
bool pngChunksFit(const std::string& data) {
    auto byte = [&](std::size_t i) { return static_cast<unsigned char>(data[i]); };
    std::size_t i = 8;  // after the signature
    while (i + 8 <= data.size()) {
        const std::uint64_t length = (std::uint64_t(byte(i)) << 24) | (std::uint64_t(byte(i + 1)) << 16) |
                                     (std::uint64_t(byte(i + 2)) << 8) | byte(i + 3);
        if (i + 12 + length > data.size()) return false;
        if (data.compare(i + 4, 4, "IEND") == 0) return true;
        i += 12 + length;
    }
    return true;
}

bool startsWith(const std::string& data, std::string_view magic) { return data.compare(0, magic.size(), magic) == 0; }
}  // namespace

Result<Image8> loadImageFile(const fs::path& path) {
    if (Status regular = checkRegularFile(path); !regular) return regular.error();
    // Stock and user textures are at most a few MiB; the limit keeps a huge file from filling memory.
    Result<std::string> bytes = readTextFile(path, std::size_t(256) << 20);
    if (!bytes) return bytes.error();
    // Shadertoy's textures are PNG and JPEG; stb's other decoders (HDR, TGA, PSD, GIF, ...) are not
    // exposed to users' files (fuzzing found endless loops and slow paths in them). JPEGs go to
    // libjpeg-turbo, the decoder browsers use (stb's JPEG decoder read past its tables and shifted
    // by negative amounts on corrupt files: tests/fuzz findings).
    const bool png = startsWith(*bytes, "\x89PNG\r\n\x1a\n");
    const bool jpeg = startsWith(*bytes, "\xFF\xD8\xFF");
    if (!png && !jpeg) return fileError(path.string(), "cannot decode image: not a PNG or JPEG file", Code::ImageDecode);
    if (jpeg)
        return decodeJpeg(std::span(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size()),
                          kMaxImageSide, path.string());
    if (!pngChunksFit(*bytes))
        return fileError(path.string(), "cannot decode image: a PNG chunk is longer than the file", Code::ImageDecode);
    int declaredWidth = 0, declaredHeight = 0, declaredChannels = 0;
    const auto* raw = reinterpret_cast<const stbi_uc*>(bytes->data());
    const int rawSize = static_cast<int>(bytes->size());
    if (stbi_info_from_memory(raw, rawSize, &declaredWidth, &declaredHeight, &declaredChannels) &&
        (declaredWidth > kMaxImageSide || declaredHeight > kMaxImageSide))
        return fileError(path.string(),
                         "the image is " + std::to_string(declaredWidth) + "x" + std::to_string(declaredHeight) +
                             ", larger than the " + std::to_string(kMaxImageSide) + " a side textures may have",
                         Code::ImageTooLarge);

    // Asking stb for 4 channels gives exactly the WebGL upload: it expands grey to R=G=B and
    // fills a missing alpha with 255, and it never applies gAMA/iCCP/sRGB chunks. The row order
    // is pinned per thread (files are top row first; flipRows below makes it bottom first).
    stbi_set_flip_vertically_on_load_thread(0);
    int width = 0, height = 0, channelsInFile = 0;
    std::unique_ptr<stbi_uc, StbFree> pixels(
        stbi_load_from_memory(raw, rawSize, &width, &height, &channelsInFile, STBI_rgb_alpha));
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        return fileError(path.string(), std::string("cannot decode image: ") + (reason ? reason : "unknown error"),
                          Code::ImageDecode);
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
