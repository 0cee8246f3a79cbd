#include "image/ImageWriters.h"

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <Imath/half.h>

#include "core/AtomicFile.h"
#include "image/ImageFile.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
constexpr const char* kExrChannels[4] = {"R", "G", "B", "A"};
constexpr int kPngReadableLimit = 1000000;

Error ioError(const fs::path& path, const std::string& what, int error) {
    return fileError(path.string(), what + ": " + std::strerror(error), error == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
}

Status checkSize(const fs::path& path, int width, int height, std::size_t values) {
    if (width <= 0 || height <= 0)
        return fileError(path.string(), "invalid image size " + std::to_string(width) + "x" + std::to_string(height),
                         Code::ImageSize);
    const std::size_t expected =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    if (values != expected)
        return fileError(path.string(), "pixel buffer holds " + std::to_string(values) + " values, " + std::to_string(width) +
                                   "x" + std::to_string(height) + " RGBA needs " + std::to_string(expected),
                         Code::ImageSize);
    return okStatus();
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
}  // namespace

Status writePng(const fs::path& path, int width, int height, std::span<const std::uint8_t> rgba,
                int compressionLevel, ImageScratch* scratch, ParentFolders parents) {
    if (Status size = checkSize(path, width, height, rgba.size()); !size) return size;
    if (compressionLevel < 0 || compressionLevel > 9)
        return fileError(path.string(), "PNG compression level must be 0..9, got " + std::to_string(compressionLevel),
                         Code::ImagePngLevel);

    // PNG stores the top row first: row i of the file is row (height-1-i) of the input. The table
    // of row pointers flips without copying pixels.
    ImageScratch local;
    std::vector<const std::uint8_t*>& rows = (scratch ? scratch : &local)->rows;
    const std::size_t stride = static_cast<std::size_t>(width) * 4;
    rows.resize(static_cast<std::size_t>(height));
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = rgba.data() + (rows.size() - 1 - i) * stride;

    // libpng's readers refuse images wider or taller than 1,000,000 pixels (their default user
    // limit), so such a file would be written but unreadable by most programs.
    if (width > kPngReadableLimit || height > kPngReadableLimit)
        return fileError(path.string(),
                         "PNG encoding failed: " + std::to_string(width) + "x" + std::to_string(height) +
                             " is larger than the 1000000 pixels a side that libpng reads",
                         Code::ImageSize);
    const auto started = std::chrono::steady_clock::now();
    PngEncoder localEncoder;
    PngEncoder& encoder = scratch ? scratch->png : localEncoder;
    const std::span<const std::uint8_t> png =
        encoder.encode(rows.data(), width, height, pngSettingsForLevel(compressionLevel));
    if (png.empty()) return fileError(path.string(), "PNG encoding failed: out of memory", Code::IoWrite);
    const auto encoded = std::chrono::steady_clock::now();
    if (scratch) scratch->encodeSeconds = std::chrono::duration<double>(encoded - started).count();
    struct WriteTimer {  // the file's write, however it ends
        ImageScratch* scratch;
        std::chrono::steady_clock::time_point from;
        ~WriteTimer() {
            if (scratch) scratch->writeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
        }
    } writeTimer{scratch, encoded};

    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::unique_ptr<std::FILE, FileCloser> file(std::fopen(temp.c_str(), "wb"));
        if (!file) return ioError(path, "cannot open for writing", errno);
        if (std::fwrite(png.data(), 1, png.size(), file.get()) != png.size()) return ioError(path, "PNG write failed", errno);
        if (std::fflush(file.get()) != 0 || std::ferror(file.get())) return ioError(path, "write failed", errno);
        if (std::fclose(file.release()) != 0) return ioError(path, "write failed", errno);
        return okStatus();
    }, parents);
}

Result<Image8> readPng(const fs::path& path) { return loadImageFile(path); }

// ---- EXR ----
namespace {
struct ExrCompressionInfo {
    ExrCompression value;
    const char* name;
    Imf::Compression imf;
};
constexpr ExrCompressionInfo kExrCompressions[] = {
    {ExrCompression::None, "none", Imf::NO_COMPRESSION},    {ExrCompression::Rle, "rle", Imf::RLE_COMPRESSION},
    {ExrCompression::Zips, "zips", Imf::ZIPS_COMPRESSION},  {ExrCompression::Zip, "zip", Imf::ZIP_COMPRESSION},
    {ExrCompression::Piz, "piz", Imf::PIZ_COMPRESSION},     {ExrCompression::Pxr24, "pxr24", Imf::PXR24_COMPRESSION},
    {ExrCompression::B44, "b44", Imf::B44_COMPRESSION},     {ExrCompression::B44a, "b44a", Imf::B44A_COMPRESSION},
    {ExrCompression::Dwaa, "dwaa", Imf::DWAA_COMPRESSION},  {ExrCompression::Dwab, "dwab", Imf::DWAB_COMPRESSION},
};
}  // namespace

std::string_view exrCompressionName(ExrCompression compression) {
    for (const ExrCompressionInfo& c : kExrCompressions)
        if (c.value == compression) return c.name;
    return "none";
}

std::optional<ExrCompression> exrCompressionNamed(std::string_view name) {
    for (const ExrCompressionInfo& c : kExrCompressions)
        if (name == c.name) return c.value;
    return std::nullopt;
}

int exrCompressionCode(ExrCompression compression) {
    for (const ExrCompressionInfo& c : kExrCompressions)
        if (c.value == compression) return static_cast<int>(c.imf);
    return static_cast<int>(Imf::NO_COMPRESSION);
}

std::string exrCompressionNames() {
    std::string names;
    for (const ExrCompressionInfo& c : kExrCompressions) names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

Status writeExr(const fs::path& path, int width, int height, std::span<const float> rgba, ImageScratch* scratch,
                ExrSettings settings, ParentFolders parents) {
    if (Status size = checkSize(path, width, height, rgba.size()); !size) return size;
    const auto started = std::chrono::steady_clock::now();
    struct EncodeTimer {
        ImageScratch* scratch;
        std::chrono::steady_clock::time_point from;
        ~EncodeTimer() {
            if (!scratch) return;
            scratch->encodeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - from).count();
            scratch->writeSeconds = 0;
        }
    } encodeTimer{scratch, started};
    ImageScratch local;
    std::vector<float>& topFirst = (scratch ? scratch : &local)->floats;
    copyFlipped(rgba, width, height, topFirst);
    std::vector<std::uint16_t>& halves = (scratch ? scratch : &local)->halves;
    if (settings.half) {  // OpenEXR does not convert slices on output: rounded to nearest here
        halves.resize(topFirst.size());
        for (std::size_t i = 0; i < topFirst.size(); ++i) halves[i] = Imath::half(topFirst[i]).bits();
    }

    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) return ioError(path, "cannot open for writing", errno);
        try {
            Imf::Header header(width, height);
            Imf::Compression compression = Imf::NO_COMPRESSION;
            for (const ExrCompressionInfo& c : kExrCompressions)
                if (c.value == settings.compression) compression = c.imf;
            header.compression() = compression;
            header.lineOrder() = Imf::INCREASING_Y;
            Imf::FrameBuffer frame;
            const Imf::PixelType type = settings.half ? Imf::HALF : Imf::FLOAT;
            const std::size_t pixelBytes = 4 * (settings.half ? sizeof(std::uint16_t) : sizeof(float));
            for (int c = 0; c < 4; ++c) {
                header.channels().insert(kExrChannels[c], Imf::Channel(type));
                char* base = settings.half ? reinterpret_cast<char*>(halves.data() + c)
                                           : reinterpret_cast<char*>(topFirst.data() + c);
                frame.insert(kExrChannels[c],
                             Imf::Slice(type, base, pixelBytes, pixelBytes * static_cast<std::size_t>(width)));
            }
            Imf::StdOFStream stream(out, temp.c_str());
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        } catch (const std::exception& e) {
            const int cause = errno;
            if (cause == ENOSPC) return ioError(path, "cannot write EXR", cause);
            return fileError(path.string(), std::string("cannot write EXR: ") + e.what(), Code::IoWrite);
        }
        out.close();  // the OutputFile above has written its offset table by now
        if (!out) return ioError(path, "write failed", errno);
        return okStatus();
    }, parents);
}

namespace {
// The size OpenEXR reads for an attribute of `type`, for the types whose values have a fixed size
// (OpenEXR's standard attribute types); nothing for the others (strings, lists, unknown types).
std::optional<std::uint64_t> exrFixedAttributeSize(std::string_view type) {
    static const std::pair<std::string_view, std::uint64_t> kSizes[] = {
        {"box2i", 16}, {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"deepImageState", 1},
        {"double", 8}, {"envmap", 1}, {"float", 4}, {"int", 4}, {"keycode", 28}, {"lineOrder", 1},
        {"m33f", 36}, {"m33d", 72}, {"m44f", 64}, {"m44d", 128}, {"rational", 8}, {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8}, {"v2f", 8}, {"v2d", 16}, {"v3i", 12}, {"v3f", 12}, {"v3d", 24},
    };
    for (const auto& [name, size] : kSizes)
        if (name == type) return size;
    return std::nullopt;
}

// The EXR header's attributes, walked before OpenEXR parses them: OpenEXR allocates an
// attribute's declared size before reading it, so a 15-byte file can ask for gigabytes (a fuzz
// finding). Every attribute must fit in the file.
Status exrHeaderFits(const fs::path& path) {
    Result<std::string> bytes = readTextFile(path, std::size_t(1) << 30);
    if (!bytes) return bytes.error();
    const std::string& d = *bytes;
    auto bad = [&](const char* what) {
        return fileError(path.string(), std::string("not a readable EXR file: ") + what, Code::ImageDecode);
    };
    if (d.size() < 8 || d.compare(0, 4, "\x76\x2f\x31\x01") != 0) return bad("no EXR signature");
    // Buffer dumps are single-part scanline or tiled images; multi-part and deep files have more
    // headers than the walk below checks, so they are refused (a fuzz finding allocated from one).
    if (static_cast<unsigned char>(d[5]) & 0x18) return bad("multi-part and deep EXR files are not supported");
    std::size_t i = 8;
    for (int attribute = 0; attribute < 10000; ++attribute) {
        if (i >= d.size()) return bad("the header is truncated");
        if (d[i] == '\0') return okStatus();  // end of the header
        const std::size_t nameEnd = d.find('\0', i);
        if (nameEnd == std::string::npos) return bad("the header is truncated");
        const std::size_t typeEnd = d.find('\0', nameEnd + 1);
        if (typeEnd == std::string::npos || typeEnd + 5 > d.size()) return bad("the header is truncated");
        const auto byte = [&](std::size_t k) { return static_cast<std::uint64_t>(static_cast<unsigned char>(d[k])); };
        const std::uint64_t size = byte(typeEnd + 1) | byte(typeEnd + 2) << 8 | byte(typeEnd + 3) << 16 |
                                   byte(typeEnd + 4) << 24;
        if (typeEnd + 5 + size > d.size()) return bad("an attribute is larger than the file");
        // OpenEXR reads an attribute of a known fixed-size type by its type's size, whatever size
        // it declares: a declaration that differs desynchronises every later attribute, and the
        // walk above would then check other bytes than OpenEXR reads (a fuzz finding: a box2i that
        // declared 0 bytes, after which OpenEXR took text for a size of 1.7 GB).
        const std::string_view type(d.data() + nameEnd + 1, typeEnd - nameEnd - 1);
        if (const std::optional<std::uint64_t> fixed = exrFixedAttributeSize(type); fixed && size != *fixed)
            return bad("an attribute's declared size does not match its type");
        // A preview image is read as its width and height, then that many RGBA pixels (allocated
        // from the width and height): they must be exactly what the attribute holds.
        if (type == "preview") {
            if (size < 8) return bad("an attribute's declared size does not match its type");
            const std::uint64_t at = typeEnd + 5;
            const std::uint64_t w = byte(at) | byte(at + 1) << 8 | byte(at + 2) << 16 | byte(at + 3) << 24;
            const std::uint64_t h = byte(at + 4) | byte(at + 5) << 8 | byte(at + 6) << 16 | byte(at + 7) << 24;
            if (8 + 4 * w * h != size) return bad("an attribute's declared size does not match its type");
        }
        // OpenEXR reads a channel list to its terminating NUL whatever size the attribute declares;
        // a list that does not end exactly at its declared size desynchronises every later
        // attribute (a fuzz finding). Entries: name, NUL, 16 bytes; then one NUL.
        if (d.compare(nameEnd + 1, typeEnd - nameEnd - 1, "chlist") == 0) {
            std::size_t at = typeEnd + 5;
            const std::size_t end = at + size;
            while (at < end && d[at] != '\0') {
                const std::size_t nul = d.find('\0', at);
                if (nul == std::string::npos || nul + 17 > end) return bad("its channel list does not fit its size");
                at = nul + 17;
            }
            if (at + 1 != end) return bad("its channel list does not fit its size");
        }
        // OpenEXR sizes its line buffers from the data window when the file is opened, before
        // toyhost could look: a window of millions of pixels is refused here (a fuzz finding).
        if (d.compare(i, nameEnd - i, "dataWindow") == 0 && size == 16) {
            auto int32 = [&](std::size_t k) {
                return static_cast<std::int32_t>(static_cast<std::uint32_t>(byte(k) | byte(k + 1) << 8 |
                                                                            byte(k + 2) << 16 | byte(k + 3) << 24));
            };
            const std::size_t at = typeEnd + 5;
            const long long width = static_cast<long long>(int32(at + 8)) - int32(at) + 1;
            const long long height = static_cast<long long>(int32(at + 12)) - int32(at + 4) + 1;
            if (width < 1 || height < 1 || width > 16384 || height > 16384)
                return fileError(path.string(),
                                 "the EXR's data window is " + std::to_string(width) + "x" + std::to_string(height) +
                                     ", not 1x1 .. 16384x16384",
                                 Code::ImageTooLarge);
        }
        i = typeEnd + 5 + size;
    }
    return bad("too many header attributes");
}
}  // namespace

Result<ImageF32> readExr(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) return fileError(path.string(), "file not found", Code::IoNotFound);
    if (!fs::is_regular_file(status)) return fileError(path.string(), "is not a regular file", Code::IoNotAFile);
    if (Status sane = exrHeaderFits(path); !sane) return sane.error();
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
        const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
        // OpenEXR allocates nothing for pixels itself; this reader would (a fuzz finding).
        if (width < 1 || height < 1 || width > 16384 || height > 16384)
            return fileError(path.string(),
                             "the EXR's data window is " + std::to_string(width) + "x" + std::to_string(height) +
                                 ", not 1x1 .. 16384x16384",
                             Code::ImageTooLarge);
        std::vector<float> topFirst(static_cast<std::size_t>(width) *
                                    static_cast<std::size_t>(height) * 4);
        Imf::FrameBuffer frame;
        const std::size_t pixelBytes = 4 * sizeof(float);
        for (int c = 0; c < 4; ++c) {
            frame.insert(kExrChannels[c],
                         Imf::Slice::Make(Imf::FLOAT, topFirst.data() + c, window, pixelBytes,
                                          pixelBytes * static_cast<std::size_t>(width), 1, 1,
                                          c == 3 ? 1.0 : 0.0));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
        flipRows(std::span<float>(topFirst), static_cast<int>(width), static_cast<int>(height));
        return ImageF32{static_cast<int>(width), static_cast<int>(height), std::move(topFirst)};
    } catch (const std::exception& e) {
        return fileError(path.string(), std::string("not a readable EXR file: ") + e.what(), Code::ImageDecode);
    }
}

}  // namespace toyhost
