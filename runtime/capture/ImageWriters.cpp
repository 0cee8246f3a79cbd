#include "capture/ImageWriters.h"

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <png.h>

#include "core/AtomicFile.h"
#include "media/ImageFile.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
constexpr const char* kExrChannels[4] = {"R", "G", "B", "A"};

Status checkSize(const fs::path& path, int width, int height, std::size_t values) {
    if (width <= 0 || height <= 0)
        return Error{path.string() + ": invalid image size " + std::to_string(width) + "x" +
                     std::to_string(height)};
    const std::size_t expected =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    if (values != expected)
        return Error{path.string() + ": pixel buffer holds " + std::to_string(values) +
                     " values, " + std::to_string(width) + "x" + std::to_string(height) +
                     " RGBA needs " + std::to_string(expected)};
    return okStatus();
}

// ---- PNG ----
// libpng reports errors by longjmp. The jump target lives in encodePng, whose frame holds only C
// objects, so no C++ destructor is ever skipped; the caller owns the FILE and the row table.
struct PngError {
    char message[256];
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto* error = static_cast<PngError*>(png_get_error_ptr(png));
    std::snprintf(error->message, sizeof error->message, "%s", message);
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // library code does not print

bool encodePng(std::FILE* file, png_bytep* rows, png_uint_32 width, png_uint_32 height, int level,
               PngError* error) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, error, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        std::snprintf(error->message, sizeof error->message, "out of memory");
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, file);
    png_set_compression_level(png, level);
    // libpng's adaptive row filters cost about as much as zlib's fastest level itself; at the
    // fast levels (capture) they are skipped, which on rendered frames costs little size.
    if (level <= 2) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
}  // namespace

Status writePng(const fs::path& path, int width, int height,
                std::span<const std::uint8_t> rgbaBottomUp, int compressionLevel) {
    if (Status size = checkSize(path, width, height, rgbaBottomUp.size()); !size) return size;
    if (compressionLevel < 0 || compressionLevel > 9)
        return Error{path.string() + ": PNG compression level must be 0..9, got " +
                     std::to_string(compressionLevel)};

    // PNG stores the top row first: row i of the file is row (height-1-i) of the input.
    const std::size_t stride = static_cast<std::size_t>(width) * 4;
    std::vector<png_bytep> rows(static_cast<std::size_t>(height));
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = const_cast<png_bytep>(rgbaBottomUp.data() + (rows.size() - 1 - i) * stride);

    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::unique_ptr<std::FILE, FileCloser> file(std::fopen(temp.c_str(), "wb"));
        if (!file)
            return Error{path.string() + ": cannot open for writing: " + std::strerror(errno)};
        PngError error{};
        if (!encodePng(file.get(), rows.data(), static_cast<png_uint_32>(width),
                       static_cast<png_uint_32>(height), compressionLevel, &error))
            return Error{path.string() + ": PNG encoding failed: " + error.message};
        if (std::fclose(file.release()) != 0)
            return Error{path.string() + ": write failed: " + std::strerror(errno)};
        return okStatus();
    });
}

Result<Image8> readPng(const fs::path& path) { return loadImageFile(path); }

// ---- EXR ----
Status writeExr(const fs::path& path, int width, int height, std::span<const float> rgbaBottomUp) {
    if (Status size = checkSize(path, width, height, rgbaBottomUp.size()); !size) return size;
    std::vector<float> topFirst = flipRows(rgbaBottomUp, width, height);

    return writeFileAtomically(path, [&](const fs::path& temp) -> Status {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out)
            return Error{path.string() + ": cannot open for writing: " + std::strerror(errno)};
        try {
            Imf::Header header(width, height);
            header.compression() = Imf::NO_COMPRESSION;
            header.lineOrder() = Imf::INCREASING_Y;
            Imf::FrameBuffer frame;
            const std::size_t pixelBytes = 4 * sizeof(float);
            for (int c = 0; c < 4; ++c) {
                header.channels().insert(kExrChannels[c], Imf::Channel(Imf::FLOAT));
                frame.insert(kExrChannels[c],
                             Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(topFirst.data() + c),
                                        pixelBytes, pixelBytes * static_cast<std::size_t>(width)));
            }
            Imf::StdOFStream stream(out, temp.c_str());
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(height);
        } catch (const std::exception& e) {
            return Error{path.string() + ": cannot write EXR: " + e.what()};
        }
        out.close();  // the OutputFile above has written its offset table by now
        if (!out) return Error{path.string() + ": write failed: " + std::strerror(errno)};
        return okStatus();
    });
}

Result<ImageF32> readExr(const fs::path& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return Error{path.string() + ": file not found"};
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int width = window.max.x - window.min.x + 1;
        const int height = window.max.y - window.min.y + 1;
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
        return ImageF32{width, height, flipRows(std::span<const float>(topFirst), width, height)};
    } catch (const std::exception& e) {
        return Error{path.string() + ": cannot read EXR: " + e.what()};
    }
}

}  // namespace toyhost
