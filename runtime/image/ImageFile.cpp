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
struct StbFree {
    void operator()(stbi_uc* pixels) const { stbi_image_free(pixels); }
};
}  // namespace

namespace {
// The largest side a texture may have (toyhost's canvas limit, core/Defaults.h).
constexpr int kMaxImageSide = 16384;

// Debian's stb_image (2.27) builds a JPEG Huffman table from the 16 code counts of a DHT segment
// without checking that they add up to at most 256, and writes past its table when they do (found
// by tests/fuzz). Such a file is refused before stb sees it, and so is a scan that names a table
// never defined. Walks the markers, also between the scans of a progressive JPEG.
bool jpegHuffmanTablesValid(const std::string& data) {
    auto byte = [&](std::size_t i) { return static_cast<unsigned char>(data[i]); };
    if (data.size() < 4 || byte(0) != 0xFF || byte(1) != 0xD8) return true;  // not a JPEG: stb decides
    std::size_t i = 2;
    bool defined[2][4] = {};  // [DC, AC][table 0..3]
    bool sequential = false, progressive = false;
    while (i + 4 <= data.size()) {
        if (byte(i) != 0xFF) {
            ++i;  // entropy-coded data of a scan: look for the next marker
            continue;
        }
        const unsigned marker = byte(i + 1);
        if (marker == 0xFF || marker == 0x00 || (marker >= 0xD0 && marker <= 0xD7) || marker == 0x01) {
            i += marker == 0xFF ? 1 : 2;  // fill byte, stuffed 0xFF00, restart marker, TEM
            continue;
        }
        if (marker == 0xD9) return true;  // end of image
        const std::size_t length = (std::size_t(byte(i + 2)) << 8) | byte(i + 3);
        // Truncated: stb reports it, except in a DHT, where it reads zeros past the end and
        // counts whatever came before into the table.
        if (length < 2 || i + 2 + length > data.size()) return marker != 0xC4;
        if (marker == 0xC4) {
            std::size_t at = i + 4;
            const std::size_t end = i + 2 + length;
            while (at < end) {
                if (at + 17 > end) return false;
                std::size_t codes = 0;
                for (int k = 1; k <= 16; ++k) codes += byte(at + k);
                if (codes > 256 || at + 17 + codes > end) return false;
                if ((byte(at) >> 4) < 2 && (byte(at) & 15) < 4) defined[byte(at) >> 4][byte(at) & 15] = true;
                at += 17 + codes;
            }
        }
        if (marker == 0xC0 || marker == 0xC1) sequential = true;
        if (marker == 0xC2) progressive = true;
        // A scan decodes with the tables its components name; stb reads a table that was never
        // defined (uninitialised memory, fuzz findings) instead of failing. A sequential scan uses
        // DC and AC tables; a progressive scan uses DC tables in a first DC pass (Ss = 0, Ah = 0),
        // none in a DC refinement, and AC tables in a spectral band (Ss > 0).
        if (marker == 0xDA && (sequential || progressive)) {
            const std::size_t components = byte(i + 4);
            if (length < 6 + 2 * components) return false;
            const unsigned spectralStart = byte(i + 5 + 2 * components);
            const unsigned approximationHigh = byte(i + 7 + 2 * components) >> 4;
            const bool usesDc = sequential || (spectralStart == 0 && approximationHigh == 0);
            const bool usesAc = sequential || spectralStart > 0;
            for (std::size_t k = 0; k < components; ++k) {
                const unsigned tables = byte(i + 6 + 2 * k);
                if (usesDc && ((tables >> 4) > 3 || !defined[0][tables >> 4])) return false;
                if (usesAc && ((tables & 15) > 3 || !defined[1][tables & 15])) return false;
            }
        }
        i += 2 + length;
    }
    return true;
}
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
    // exposed to users' files (fuzzing found endless loops and slow paths in them).
    const bool png = startsWith(*bytes, "\x89PNG\r\n\x1a\n");
    const bool jpeg = startsWith(*bytes, "\xFF\xD8\xFF");
    if (!png && !jpeg) return fileError(path.string(), "cannot decode image: not a PNG or JPEG file", Code::ImageDecode);
    if (jpeg && !jpegHuffmanTablesValid(*bytes))
        return fileError(path.string(), "cannot decode image: a JPEG Huffman table (DHT) is malformed", Code::ImageDecode);
    if (png && !pngChunksFit(*bytes))
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
