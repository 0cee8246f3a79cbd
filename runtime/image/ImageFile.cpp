#include "image/ImageFile.h"

#include <new>
#include <string>
#include <string_view>

#include "core/AtomicFile.h"
#include "image/JpegDecode.h"
#include "image/PngDecode.h"
#include "image/PixelMemory.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
// Every PNG chunk fits in the file: a chunk that claims more than the file holds is named as such
// (the decoder before libpng allocated a chunk's declared length before reading it: a 41-byte
// file asked for gigabytes, a fuzz finding).
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
    Result<std::string> bytes = Error("unread");
    try {
        bytes = readTextFile(path, std::size_t(256) << 20);
    } catch (const std::bad_alloc&) {
        std::error_code ec;
        return notEnoughMemory(path.string(), "reading the file", formatBytes(std::filesystem::file_size(path, ec)));
    }
    if (!bytes) return bytes.error();
    // Shadertoy's textures are PNG and JPEG, decoded by libpng and libjpeg-turbo, the decoders
    // browsers have used. (stb_image, used before, read past its tables, shifted by negative
    // amounts and offset null pointers on corrupt files: tests/fuzz findings; its other formats,
    // HDR, TGA, PSD, GIF, are not Shadertoy's and stay unsupported.)
    const bool png = startsWith(*bytes, "\x89PNG\r\n\x1a\n");
    const bool jpeg = startsWith(*bytes, "\xFF\xD8\xFF");
    if (!png && !jpeg) return fileError(path.string(), "cannot decode image: not a PNG or JPEG file", Code::ImageDecode);
    if (jpeg)
        return decodeJpeg(std::span(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size()),
                          DecodeLimits{}, path.string());
    if (!pngChunksFit(*bytes))
        return fileError(path.string(), "cannot decode image: a PNG chunk is longer than the file", Code::ImageDecode);
    return decodePng(std::span(reinterpret_cast<const unsigned char*>(bytes->data()), bytes->size()), DecodeLimits{},
                     path.string());
}

}  // namespace toyhost
