// png_candidates: measures PNG encoders on real frames (raw RGBA8 files as `toyhost run --out -`
// writes them, rows top first): libpng + zlib as toyhost wrote PNG before, and toyhost's
// PngEncoder (libdeflate) at several deflate levels and row filters, and its fast path. For each:
// the median CPU time of the encoding thread (ms), MB/s of input on one thread, file size, and
// whether libpng decodes it to the same pixels. CPU only, no GL.
//
// usage: png_candidates [--quick] WIDTH HEIGHT REPS frame.rgba...
// (--quick: only the encoder before, libdeflate 1 unfiltered and the fast path)
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <png.h>

#include "image/PngEncoder.h"

namespace {
using namespace toyhost;

struct Memory {
    std::vector<std::uint8_t> bytes;
};
void appendBytes(png_structp png, png_bytep data, png_size_t size) {
    auto* m = static_cast<Memory*>(png_get_io_ptr(png));
    m->bytes.insert(m->bytes.end(), data, data + size);
}
void noFlush(png_structp) {}

// The encoder toyhost used before: libpng, zlib level `level`, rows unfiltered at levels <= 2.
std::vector<std::uint8_t> libpngEncode(const std::vector<const std::uint8_t*>& rows, int w, int h, int level) {
    Memory m;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) std::abort();
    png_set_write_fn(png, &m, appendBytes, noFlush);
    png_set_compression_level(png, level);
    if (level <= 2) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_write_image(png, const_cast<png_bytepp>(rows.data()));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return m.bytes;
}

// This thread's CPU time: on a machine shared with other work it moves far less than the wall
// clock (which counts the time other processes hold the core).
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

bool decodesTo(const std::vector<std::uint8_t>& file, const std::vector<std::uint8_t>& pixels, int w, int h) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) return false;
    image.format = PNG_FORMAT_RGBA;
    if (static_cast<int>(image.width) != w || static_cast<int>(image.height) != h) return false;
    std::vector<std::uint8_t> out(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.data(), 0, nullptr)) return false;
    return out == pixels;
}

const char* filterName(PngFilter f) {
    switch (f) {
    case PngFilter::None: return "none";
    case PngFilter::Sub: return "sub";
    case PngFilter::Up: return "up";
    case PngFilter::Paeth: return "paeth";
    case PngFilter::Adaptive: return "adaptive";
    }
    return "?";
}
}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
    if (quick) {
        --argc;
        ++argv;
    }
    if (argc < 5) {
        std::fprintf(stderr, "usage: png_candidates [--quick] WIDTH HEIGHT REPS frame.rgba...\n");
        return 2;
    }
    const int w = std::atoi(argv[1]), h = std::atoi(argv[2]), reps = std::atoi(argv[3]);
    const std::size_t frameBytes = static_cast<std::size_t>(w) * h * 4;
    for (int f = 4; f < argc; ++f) {
        std::ifstream in(argv[f], std::ios::binary);
        std::vector<std::uint8_t> pixels((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (pixels.size() != frameBytes) {
            std::fprintf(stderr, "%s: %zu bytes, expected %zu\n", argv[f], pixels.size(), frameBytes);
            return 1;
        }
        std::vector<const std::uint8_t*> rows(h);
        for (int y = 0; y < h; ++y) rows[y] = pixels.data() + static_cast<std::size_t>(y) * w * 4;
        auto measure = [&](const char* name, auto&& encode) {
            std::vector<double> ms;
            std::vector<std::uint8_t> file;
            for (int r = 0; r < reps; ++r) {
                const double t0 = threadCpuMs();
                file = encode();
                ms.push_back(threadCpuMs() - t0);
            }
            std::sort(ms.begin(), ms.end());
            const double median = ms[ms.size() / 2];
            std::printf("%s\t%s\t%.1f\t%.0f\t%zu\t%.3f\t%s\n", argv[f], name, median, frameBytes / median / 1000.0,
                        file.size(), double(file.size()) / frameBytes, decodesTo(file, pixels, w, h) ? "exact" : "WRONG");
            std::fflush(stdout);
        };
        std::printf("frame\tencoder\tms\tMB/s\tbytes\tratio\tlibpng\n");
        measure("libpng+zlib-1 (before)", [&] { return libpngEncode(rows, w, h, 1); });
        if (!quick) measure("libpng+zlib-6 adaptive", [&] { return libpngEncode(rows, w, h, 6); });
        PngEncoder encoder;
        for (PngFilter filter : {PngFilter::Adaptive, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth}) {
            const std::string name = std::string("fast-runs ") + filterName(filter);
            measure(name.c_str(), [&] {
                std::span<const std::uint8_t> s = encoder.encode(rows.data(), w, h, {1, filter, PngDeflate::FastRuns});
                return std::vector<std::uint8_t>(s.begin(), s.end());
            });
        }
        if (quick) {
            measure("libdeflate-1 none", [&] {
                std::span<const std::uint8_t> s = encoder.encode(rows.data(), w, h, {1, PngFilter::None});
                return std::vector<std::uint8_t>(s.begin(), s.end());
            });
            continue;
        }
        for (int level : {0, 1, 4, 6, 12})
            for (PngFilter filter :
                 {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Paeth, PngFilter::Adaptive}) {
                if (level == 0 && filter != PngFilter::None) continue;
                if (level == 12 && reps > 1 && filter != PngFilter::Adaptive && filter != PngFilter::Up) continue;
                const std::string name = "libdeflate-" + std::to_string(level) + " " + filterName(filter);
                measure(name.c_str(), [&] {
                    std::span<const std::uint8_t> s = encoder.encode(rows.data(), w, h, {level, filter});
                    return std::vector<std::uint8_t>(s.begin(), s.end());
                });
            }
    }
    return 0;
}
