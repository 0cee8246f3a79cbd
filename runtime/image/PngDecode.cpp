#include "image/PngDecode.h"

#include <chrono>
#include <csetjmp>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

#include <png.h>

#include "core/ThreadCpuClock.h"
#include "image/DecodeLimits.h"
#include "image/PixelMemory.h"

namespace toyhost {

namespace {

// Deflate cannot expand data more than 1032 times (258 bytes from one 2-bit code, in theory; zlib's
// documentation gives 1032:1 as the limit). A file smaller than its declared image divided by that
// cannot hold it: refused before the picture's memory is allocated (a 100-byte file can declare
// 16384x16384).
constexpr std::uint64_t kDeflateMaxRatio = 1032;

// Everything decodeInto() touches lives here, outside its frame: libpng reports errors by
// longjmp back to decodeInto(), and no C++ object with a destructor may be jumped over.
struct Job {
    png_structp png;
    png_infop info;
    const unsigned char* data;
    std::size_t size;
    std::size_t at;  // read position in data
    DecodeLimits limits;
    ThreadCpuClock::time_point deadline;
    Image8* out;
    std::vector<png_bytep>* rows;
    char message[256];
    bool tooLarge;
    bool tooShort;
    bool tooSlow;
    bool outOfMemory;  // the decoded picture could not be allocated
};

void onError(png_structp png, png_const_charp message) {
    auto* job = static_cast<Job*>(png_get_error_ptr(png));
    std::strncpy(job->message, message ? message : "unknown error", sizeof job->message - 1);
    png_longjmp(png, 1);
}

void onWarning(png_structp, png_const_charp) {}  // ancillary-chunk trouble: the picture is still read

void onRead(png_structp png, png_bytep out, png_size_t length) {
    auto* job = static_cast<Job*>(png_get_io_ptr(png));
    if (length > job->size - job->at) png_error(png, "the PNG data ends before the image does (a truncated file?)");
    std::memcpy(out, job->data + job->at, length);
    job->at += length;
}

// Called after each row libpng decodes: the place a decode that outlasts its time is stopped.
void onRow(png_structp png, png_uint_32, int) {
    auto* job = static_cast<Job*>(png_get_error_ptr(png));
    if (ThreadCpuClock::now() < job->deadline) return;
    job->tooSlow = true;
    png_error(png, "too slow");
}

// Returns false with job.message set (or tooLarge / tooShort) when the file cannot be decoded.
bool decodeInto(Job& job) {
    job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, onError, onWarning);
    if (!job.png) {
        std::strncpy(job.message, "libpng could not start", sizeof job.message - 1);
        return false;
    }
    job.info = png_create_info_struct(job.png);
    if (!job.info) {
        png_destroy_read_struct(&job.png, nullptr, nullptr);
        std::strncpy(job.message, "libpng could not start", sizeof job.message - 1);
        return false;
    }
    if (setjmp(png_jmpbuf(job.png))) {
        png_destroy_read_struct(&job.png, &job.info, nullptr);
        return false;
    }
    png_set_read_fn(job.png, &job, onRead);
    png_read_info(job.png, job.info);
    const png_uint_32 width = png_get_image_width(job.png, job.info);
    const png_uint_32 height = png_get_image_height(job.png, job.info);
    job.out->width = static_cast<int>(width);
    job.out->height = static_cast<int>(height);
    if (width > static_cast<png_uint_32>(job.limits.maxSide) || height > static_cast<png_uint_32>(job.limits.maxSide)) {
        job.tooLarge = true;
        png_destroy_read_struct(&job.png, &job.info, nullptr);
        return false;
    }
    // The filtered image data the header implies: a filter byte and the packed pixels per row.
    const std::uint64_t bitsPerPixel =
        std::uint64_t(png_get_channels(job.png, job.info)) * png_get_bit_depth(job.png, job.info);
    const std::uint64_t inflated = std::uint64_t(height) * (1 + (std::uint64_t(width) * bitsPerPixel + 7) / 8);
    if (std::uint64_t(job.size) * kDeflateMaxRatio < inflated) {
        job.tooShort = true;
        png_destroy_read_struct(&job.png, &job.info, nullptr);
        return false;
    }

    png_set_expand(job.png);     // palette to RGB, grey below 8 bits to 8, tRNS to alpha
    png_set_strip_16(job.png);   // 16-bit channels: the high byte
    png_set_gray_to_rgb(job.png);
    png_set_add_alpha(job.png, 0xFF, PNG_FILLER_AFTER);  // only where there is no alpha yet
    png_set_interlace_handling(job.png);
    png_set_read_status_fn(job.png, onRow);
    png_read_update_info(job.png, job.info);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    if (png_get_rowbytes(job.png, job.info) != rowBytes) png_error(job.png, "unexpected row layout after conversion");

    bool allocated = tryResize(job.out->rgba, rowBytes * height);
    try {
        if (allocated) job.rows->resize(height);
    } catch (const std::bad_alloc&) {
        allocated = false;
    }
    if (!allocated) {
        job.outOfMemory = true;
        png_destroy_read_struct(&job.png, &job.info, nullptr);
        return false;
    }
    for (png_uint_32 y = 0; y < height; ++y)  // files store the top row first; Image8 the bottom first
        (*job.rows)[y] = job.out->rgba.data() + static_cast<std::size_t>(height - 1 - y) * rowBytes;
    png_read_image(job.png, job.rows->data());
    // Every row is decoded: what follows (text chunks, IEND) is not read, so a file cut after its
    // image data still shows.
    png_destroy_read_struct(&job.png, &job.info, nullptr);
    return true;
}

}  // namespace

Result<Image8> decodePng(std::span<const unsigned char> bytes, const DecodeLimits& limits, const std::string& name) {
    Image8 image;
    std::vector<png_bytep> rows;
    Job job{};
    job.data = bytes.data();
    job.size = bytes.size();
    job.limits = limits;
    job.deadline = ThreadCpuClock::now() +
                   std::chrono::duration_cast<ThreadCpuClock::duration>(std::chrono::duration<double>(limits.maxSeconds));
    job.out = &image;
    job.rows = &rows;
    if (decodeInto(job)) return image;
    if (job.tooLarge) return imageTooLarge(name, image.width, image.height, limits.maxSide);
    if (job.outOfMemory) return notEnoughMemory(name, "decoding the PNG", pictureMemoryText(image.width, image.height));
    if (job.tooSlow)
        return decodeTooSlow(name, limits, "in a " + std::to_string(image.width) + "x" + std::to_string(image.height) + " PNG");
    if (job.tooShort)
        return fileError(name,
                         "cannot decode image: the PNG declares " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + " but the file is too small to hold it (a truncated file?)",
                         Code::ImageDecode);
    // libpng's own allocations ("Out of memory", "Insufficient memory") fail with a message only.
    if (std::strstr(job.message, "memory"))
        return notEnoughMemory(name, "decoding the PNG",
                               "more memory than toyhost could get (" + std::string(job.message) + ", " +
                                   std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    return fileError(name, std::string("cannot decode image: ") + job.message, Code::ImageDecode);
}

}  // namespace toyhost
