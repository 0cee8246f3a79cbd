#include "image/JpegDecode.h"

#include <chrono>
#include <csetjmp>
#include <cstddef>
#include <cstdint>
#include <cstdio>  // jpeglib.h needs FILE and size_t declared first

#include <jerror.h>
#include <jpeglib.h>

#include "core/ThreadCpuClock.h"
#include "image/DecodeLimits.h"
#include "image/PixelMemory.h"

namespace toyhost {

namespace {

// libjpeg's working memory beyond the decoded picture (a progressive JPEG keeps every DCT
// coefficient: 2 bytes a sample, about 100 MB for a 4096x4096 colour texture). A few bytes can
// declare a 16384x16384 progressive image; past this limit libjpeg stops with "insufficient memory"
// instead of allocating gigabytes.
constexpr long kMaxWorkingMemory = 512L << 20;

// libjpeg reports a fatal error by calling error_exit, which must not return: it jumps back to
// decodeInto(), which then cleans up. Warnings (corrupt data libjpeg can decode past) only count,
// except the one that says the data ended early.
struct Errors {
    jpeg_error_mgr base;  // first: libjpeg sees a pointer to it
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    int code;  // libjpeg's J_MESSAGE_CODE of the fatal error
    bool endedEarly;
};

[[noreturn]] void onError(j_common_ptr info) {
    auto* errors = reinterpret_cast<Errors*>(info->err);
    (*info->err->format_message)(info, errors->message);
    errors->code = info->err->msg_code;
    std::longjmp(errors->jump, 1);
}

void onMessage(j_common_ptr info, int level) {
    if (level < 0 && info->err->msg_code == JWRN_JPEG_EOF) reinterpret_cast<Errors*>(info->err)->endedEarly = true;
}

// The decode's own CPU time: a loaded machine or a suspension does not make a real image too slow.
using Clock = ThreadCpuClock;

// Why the progress monitor stopped the decode.
enum class Stopped { No, Scans, Time };

// Everything decodeInto() touches lives here, outside its frame, so that nothing it needs after a
// longjmp is an automatic variable changed since setjmp, and no C++ object with a destructor is
// jumped over.
struct Job {
    jpeg_decompress_struct info;
    Errors errors;
    jpeg_progress_mgr progress;
    const unsigned char* data;
    unsigned long size;
    DecodeLimits limits;
    Clock::time_point deadline;
    Stopped stopped;
    int stoppedInScan;
    bool outOfMemory;  // the decoded picture could not be allocated
    Image8* out;
    bool tooLarge;
    std::uint64_t blocks;  // 8x8 blocks over all components, when the file is too small for them
};

// libjpeg calls this before each row of blocks it reads from a scan (a progressive file's scans
// are all read inside jpeg_start_decompress) and before each row it outputs: the one place a long
// decode can be stopped. It leaves the way error_exit does.
void onProgress(j_common_ptr common) {
    Job& job = *static_cast<Job*>(common->client_data);
    if (job.info.input_scan_number > job.limits.maxScans) job.stopped = Stopped::Scans;
    else if (Clock::now() >= job.deadline) job.stopped = Stopped::Time;
    else return;
    job.stoppedInScan = job.info.input_scan_number;
    std::longjmp(job.errors.jump, 1);
}

// Adobe's CMYK JPEGs store inverted values; as Chromium: R = C*K/255 (truncated), alpha 255.
void cmykToRgba(std::uint8_t* row, std::size_t pixels) {
    for (std::size_t x = 0; x < pixels; ++x) {
        std::uint8_t* p = row + 4 * x;
        const unsigned k = p[3];
        p[0] = static_cast<std::uint8_t>(p[0] * k / 255);
        p[1] = static_cast<std::uint8_t>(p[1] * k / 255);
        p[2] = static_cast<std::uint8_t>(p[2] * k / 255);
        p[3] = 255;
    }
}

// Returns false with job.errors.message set (or job.tooLarge) when the file cannot be decoded.
bool decodeInto(Job& job) {
    job.info.err = jpeg_std_error(&job.errors.base);
    job.errors.base.error_exit = onError;
    job.errors.base.emit_message = onMessage;
    job.errors.endedEarly = false;
    job.errors.message[0] = '\0';
    if (setjmp(job.errors.jump)) {
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    jpeg_create_decompress(&job.info);
    job.info.client_data = &job;
    job.progress.progress_monitor = onProgress;
    job.info.progress = &job.progress;
    job.info.mem->max_memory_to_use = kMaxWorkingMemory;
    jpeg_mem_src(&job.info, job.data, job.size);
    jpeg_read_header(&job.info, TRUE);
    job.out->width = static_cast<int>(job.info.image_width);
    job.out->height = static_cast<int>(job.info.image_height);
    if (job.info.image_width > static_cast<JDIMENSION>(job.limits.maxSide) ||
        job.info.image_height > static_cast<JDIMENSION>(job.limits.maxSide)) {
        job.tooLarge = true;
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    // Huffman coding spends at least one bit on every 8x8 block of every component: a baseline
    // scan codes each block's DC difference and AC run with codes of 1 to 16 bits, and a
    // progressive file's first DC scan of a component codes each block's DC difference (only AC
    // scans can skip runs of blocks with one symbol, EOBRUN). A file with fewer bits than blocks
    // cannot hold the picture its header declares; libjpeg would fill the missing blocks with grey
    // after allocating the whole picture (2 KB declaring 16000x16000: 1 GB and seconds of work).
    // Arithmetic coding can spend far less than a bit on a block, so it has no such bound.
    if (!job.info.arith_code) {
        std::uint64_t blocks = 0;
        for (int c = 0; c < job.info.num_components; ++c)
            blocks += std::uint64_t(job.info.comp_info[c].width_in_blocks) * job.info.comp_info[c].height_in_blocks;
        if (std::uint64_t(job.size) * 8 < blocks) {
            job.blocks = blocks;
            jpeg_destroy_decompress(&job.info);
            return false;
        }
    }
    const bool cmyk = job.info.jpeg_color_space == JCS_CMYK || job.info.jpeg_color_space == JCS_YCCK;
    job.info.out_color_space = cmyk ? JCS_CMYK : JCS_EXT_RGBA;
    job.info.dct_method = JDCT_ISLOW;
    job.info.do_fancy_upsampling = TRUE;
    job.info.do_block_smoothing = TRUE;
    job.info.quantize_colors = FALSE;
    jpeg_start_decompress(&job.info);

    const int width = static_cast<int>(job.info.output_width);
    const int height = static_cast<int>(job.info.output_height);
    const std::size_t rowBytes = static_cast<std::size_t>(width) * 4;
    job.out->width = width;
    job.out->height = height;
    if (!tryResize(job.out->rgba, rowBytes * static_cast<std::size_t>(height))) {
        job.outOfMemory = true;
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    while (job.info.output_scanline < job.info.output_height) {
        // Files store the top row first; Image8 keeps the bottom row first.
        const std::size_t y = static_cast<std::size_t>(height) - 1 - job.info.output_scanline;
        JSAMPROW row = job.out->rgba.data() + y * rowBytes;
        if (jpeg_read_scanlines(&job.info, &row, 1) != 1) break;
        if (cmyk) cmykToRgba(row, static_cast<std::size_t>(width));
        if (job.errors.endedEarly) break;
    }
    if (job.errors.endedEarly || job.info.output_scanline < job.info.output_height) {
        jpeg_destroy_decompress(&job.info);
        return false;
    }
    // Every row was decoded without running out of data. (A file missing only its end marker is
    // still refused when the decoder's read-ahead for the last rows meets the end of the data,
    // which cannot be told from a file cut inside those rows.)
    jpeg_finish_decompress(&job.info);
    jpeg_destroy_decompress(&job.info);
    return true;
}

}  // namespace

Result<Image8> decodeJpeg(std::span<const unsigned char> bytes, const DecodeLimits& limits, const std::string& name) {
    Image8 image;
    Job job{};
    job.data = bytes.data();
    job.size = static_cast<unsigned long>(bytes.size());
    job.limits = limits;
    job.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits.maxSeconds));
    job.out = &image;
    if (decodeInto(job)) return image;
    if (job.tooLarge) return imageTooLarge(name, image.width, image.height, limits.maxSide);
    if (job.stopped == Stopped::Scans)
        return fileError(name,
                         "cannot decode image: the JPEG has more than " + std::to_string(limits.maxScans) +
                             " scans (encoders write about 10; each scan makes the decoder pass over the picture "
                             "again, so that many only slow it down)",
                         Code::ImageDecode);
    if (job.stopped == Stopped::Time)
        return decodeTooSlow(name, limits,
                             "in scan " + std::to_string(job.stoppedInScan) + " of a " +
                                 std::to_string(image.width) + "x" + std::to_string(image.height) + " JPEG");
    if (job.blocks)
        return fileError(name,
                         "cannot decode image: the JPEG declares " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + ", " + std::to_string(job.blocks) +
                             " blocks of 8x8 over its components, which take at least " +
                             std::to_string((job.blocks + 7) / 8) + " bytes of coded data, but the file has " +
                             std::to_string(bytes.size()) + " bytes (a truncated or inconsistent file?)",
                         Code::ImageDecode);
    if (job.errors.endedEarly)
        return fileError(name, "cannot decode image: the JPEG data ends before the image does (a truncated file?)",
                         Code::ImageDecode);
    if (job.outOfMemory)
        return notEnoughMemory(name, "decoding the JPEG", pictureMemoryText(image.width, image.height));
    if (job.errors.code == JERR_OUT_OF_MEMORY)
        return notEnoughMemory(name, "decoding the JPEG",
                               "more working memory than toyhost could get (its header declares " +
                                   std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    // Over the working-memory cap libjpeg asks for a backing store (temporary files), which it
    // does not have: say what that means.
    if (job.errors.code == JERR_NO_BACKING_STORE)
        return fileError(name,
                         "cannot decode image: decoding it needs more than " + std::to_string(kMaxWorkingMemory >> 20) +
                             " MiB of working memory (its header declares " + std::to_string(image.width) + "x" +
                             std::to_string(image.height) + ")",
                         Code::ImageDecode);
    return fileError(name, std::string("cannot decode image: ") + job.errors.message, Code::ImageDecode);
}

}  // namespace toyhost
