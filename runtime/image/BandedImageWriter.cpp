#include "image/BandedImageWriter.h"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

#include "core/AtomicFile.h"
#include "core/InFlight.h"

namespace toyhost {

namespace fs = std::filesystem;

struct BandedImageWriter::Impl {
    fs::path path, temp;
    int width = 0, height = 0, written = 0;
    Format format = Format::Png;
    bool finished = false;
    // PNG
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    std::string pngError;  // libpng's message for the error that longjmp'd
    int writeErrno = 0;    // why the file's write failed, when that was the error
    // EXR
    std::unique_ptr<Imf::OutputFile> exr;
    bool half = false;
    std::vector<std::uint16_t> halves;

    Error failure(const std::string& what) const { return fileError(path.string(), what, Code::IoWrite); }
    // libpng's error, or the system's reason when a write failed ("No space left on device", "File
    // too large"), as the other writers say it.
    // OpenEXR's exception, or the system's reason when the file could not take more (its message
    // names the hidden temporary file).
    Error exrFailure(const std::exception& e) const {
        const int cause = errno;
        if (cause == ENOSPC || cause == EFBIG)
            return fileError(path.string(), std::string("cannot write EXR: ") + std::strerror(cause),
                             cause == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
        return failure(std::string("cannot write EXR: ") + e.what());
    }
    Error pngFailure() const {
        if (writeErrno == 0) return failure("PNG: " + pngError);
        return fileError(path.string(), std::string("write failed: ") + std::strerror(writeErrno),
                         writeErrno == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
    }

    void closePng() {
        if (png) png_destroy_write_struct(&png, &info);
        png = nullptr;
        info = nullptr;
        if (file) std::fclose(file);
        file = nullptr;
    }
    ~Impl() {
        closePng();
        exr.reset();
        if (!finished && !temp.empty()) {
            std::error_code ec;
            fs::remove(temp, ec);
            inflight::removeFile(temp);
        }
    }
};

namespace {

void pngFailed(png_structp png, png_const_charp message) {
    auto* impl = static_cast<BandedImageWriter::Impl*>(png_get_error_ptr(png));
    impl->pngError = message ? message : "libpng error";
    png_longjmp(png, 1);
}
void pngWarning(png_structp, png_const_charp) {}

// libpng's own writer (png_init_io) reports a failed fwrite as "Write Error", without errno.
void pngWrite(png_structp png, png_bytep data, png_size_t length) {
    auto* impl = static_cast<BandedImageWriter::Impl*>(png_get_io_ptr(png));
    if (std::fwrite(data, 1, length, impl->file) != length) {
        impl->writeErrno = errno ? errno : EIO;
        png_error(png, "Write Error");
    }
}
void pngFlush(png_structp png) {
    auto* impl = static_cast<BandedImageWriter::Impl*>(png_get_io_ptr(png));
    if (std::fflush(impl->file) != 0) {
        impl->writeErrno = errno ? errno : EIO;
        png_error(png, "Write Error");
    }
}

const char* const kChannels[4] = {"R", "G", "B", "A"};

}  // namespace

BandedImageWriter::BandedImageWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
BandedImageWriter::~BandedImageWriter() = default;

Result<std::unique_ptr<BandedImageWriter>> BandedImageWriter::open(const fs::path& path, int width, int height,
                                                                   Format format, int pngLevel, ExrSettings exr) {
    auto impl = std::make_unique<Impl>();
    impl->path = path;
    impl->width = width;
    impl->height = height;
    impl->format = format;
    if (width < 1 || height < 1) return impl->failure("image size " + std::to_string(width) + "x" + std::to_string(height));
    std::error_code ec;
    if (path.has_parent_path()) {
        fs::create_directories(path.parent_path(), ec);
        if (ec) return fileError(path.parent_path().string(), "cannot create folder: " + ec.message(), Code::IoWrite);
    }
    impl->temp = temporarySibling(path);
    if (!inflight::addFile(impl->temp)) return fileError(path.string(), "not written: toyhost is stopping", Code::Interrupted);
    if (format == Format::Png) {
        impl->file = std::fopen(impl->temp.c_str(), "wb");
        if (!impl->file) return impl->failure(std::string("cannot open for writing: ") + std::strerror(errno));
        impl->png = png_create_write_struct(PNG_LIBPNG_VER_STRING, impl.get(), pngFailed, pngWarning);
        if (impl->png) impl->info = png_create_info_struct(impl->png);
        if (!impl->png || !impl->info) return impl->failure("PNG: out of memory");
        if (setjmp(png_jmpbuf(impl->png))) return impl->pngFailure();
        png_set_write_fn(impl->png, impl.get(), pngWrite, pngFlush);
        png_set_compression_level(impl->png, pngLevel);
        png_set_filter(impl->png, PNG_FILTER_TYPE_BASE, pngLevel == 0 ? PNG_FILTER_NONE : PNG_FILTER_UP);
        png_set_IHDR(impl->png, impl->info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                     PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
        png_write_info(impl->png, impl->info);
    } else {
        try {
            Imf::Header header(width, height);
            header.compression() = static_cast<Imf::Compression>(exrCompressionCode(exr.compression));
            header.lineOrder() = Imf::INCREASING_Y;
            for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(exr.half ? Imf::HALF : Imf::FLOAT));
            impl->half = exr.half;
            impl->exr = std::make_unique<Imf::OutputFile>(impl->temp.c_str(), header);
        } catch (const std::exception& e) {
            return impl->exrFailure(e);
        }
    }
    return std::unique_ptr<BandedImageWriter>(new BandedImageWriter(std::move(impl)));
}

Status BandedImageWriter::writeRows(std::span<const std::uint8_t> rgba, int rows) {
    Impl& s = *impl_;
    if (s.format != Format::Png) return s.failure("internal: 8-bit rows for an EXR file");
    if (rows < 0 || s.written + rows > s.height || rgba.size() < static_cast<std::size_t>(rows) * s.width * 4)
        return s.failure("internal: rows beyond the image");
    if (setjmp(png_jmpbuf(s.png))) return s.pngFailure();
    for (int r = 0; r < rows; ++r)
        png_write_row(s.png, rgba.data() + static_cast<std::size_t>(r) * s.width * 4);
    s.written += rows;
    return okStatus();
}

Status BandedImageWriter::writeRows(std::span<const float> rgba, int rows) {
    Impl& s = *impl_;
    if (s.format != Format::Exr) return s.failure("internal: float rows for a PNG file");
    if (rows < 0 || s.written + rows > s.height || rgba.size() < static_cast<std::size_t>(rows) * s.width * 4)
        return s.failure("internal: rows beyond the image");
    try {
        const std::size_t rowValues = static_cast<std::size_t>(s.width) * 4;
        Imf::FrameBuffer frame;
        // The slice's base is where pixel (0, 0) would be: these rows start at y = written.
        if (s.half) {
            s.halves.resize(static_cast<std::size_t>(rows) * rowValues);
            for (std::size_t i = 0; i < s.halves.size(); ++i) s.halves[i] = Imath::half(rgba[i]).bits();
            char* base = reinterpret_cast<char*>(s.halves.data()) -
                         static_cast<std::ptrdiff_t>(static_cast<std::size_t>(s.written) * rowValues * 2);
            for (int c = 0; c < 4; ++c)
                frame.insert(kChannels[c], Imf::Slice(Imf::HALF, base + c * 2, 8, rowValues * 2));
        } else {
            char* base = reinterpret_cast<char*>(const_cast<float*>(rgba.data())) -
                         static_cast<std::ptrdiff_t>(static_cast<std::size_t>(s.written) * rowValues * 4);
            for (int c = 0; c < 4; ++c)
                frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, base + c * 4, 16, rowValues * 4));
        }
        s.exr->setFrameBuffer(frame);
        s.exr->writePixels(rows);
    } catch (const std::exception& e) {
        return s.exrFailure(e);
    }
    s.written += rows;
    return okStatus();
}

Status BandedImageWriter::finish() {
    Impl& s = *impl_;
    if (s.written != s.height)
        return s.failure("internal: " + std::to_string(s.written) + " of " + std::to_string(s.height) + " rows written");
    if (s.format == Format::Png) {
        if (setjmp(png_jmpbuf(s.png))) return s.pngFailure();
        png_write_end(s.png, nullptr);
        png_destroy_write_struct(&s.png, &s.info);
        s.png = nullptr;
        s.info = nullptr;
        const bool flushed = std::fflush(s.file) == 0 && !std::ferror(s.file);
        int cause = errno;
        const bool closed = std::fclose(s.file) == 0;
        if (flushed && !closed) cause = errno;
        s.file = nullptr;
        if (!flushed || !closed)
            return fileError(s.path.string(), std::string("write failed: ") + std::strerror(cause),
                             cause == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
    } else {
        try {
            s.exr.reset();  // writes the offset table and closes the file
        } catch (const std::exception& e) {
            return s.exrFailure(e);
        }
    }
    std::error_code ec;
    fs::rename(s.temp, s.path, ec);
    if (ec) return s.failure("cannot rename the temporary file into place: " + ec.message());
    inflight::removeFile(s.temp);
    s.finished = true;
    return okStatus();
}

}  // namespace toyhost
