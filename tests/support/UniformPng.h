// UniformPng: writes a PNG of one RGBA colour at any size, compressed as it is written (zlib,
// streamed row by row), so that a test can make a 16384x16384 picture (1 GiB decoded) as a file of
// about 1 MiB without holding the picture. No GL.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <zlib.h>

namespace toyhost::testing {

inline void appendU32(std::string& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((value >> shift) & 255));
}

inline void appendChunk(std::string& out, const char* type, const std::string& data) {
    appendU32(out, static_cast<std::uint32_t>(data.size()));
    const std::string typed = std::string(type, 4) + data;
    out += typed;
    appendU32(out, static_cast<std::uint32_t>(
                       crc32(0, reinterpret_cast<const Bytef*>(typed.data()), static_cast<uInt>(typed.size()))));
}

// Writes `file`: width x height, 8-bit RGBA, every pixel `rgba`. Returns false when zlib fails.
inline bool writeUniformPng(const std::filesystem::path& file, int width, int height, std::array<std::uint8_t, 4> rgba) {
    std::string header;
    appendU32(header, static_cast<std::uint32_t>(width));
    appendU32(header, static_cast<std::uint32_t>(height));
    header += std::string("\x08\x06\x00\x00\x00", 5);  // 8 bits, RGBA, deflate, no filter method, no interlace
    std::vector<std::uint8_t> row(1 + std::size_t(width) * 4);
    row[0] = 0;  // no filter
    for (int x = 0; x < width; ++x)
        for (int c = 0; c < 4; ++c) row[1 + std::size_t(x) * 4 + c] = rgba[c];
    z_stream z{};
    if (deflateInit(&z, Z_BEST_COMPRESSION) != Z_OK) return false;
    std::string compressed;
    std::vector<std::uint8_t> out(1 << 16);
    for (int y = 0; y <= height; ++y) {
        const bool last = y == height;
        z.next_in = last ? nullptr : row.data();
        z.avail_in = last ? 0 : static_cast<uInt>(row.size());
        int status;
        do {
            z.next_out = out.data();
            z.avail_out = static_cast<uInt>(out.size());
            status = deflate(&z, last ? Z_FINISH : Z_NO_FLUSH);
            compressed.append(reinterpret_cast<const char*>(out.data()), out.size() - z.avail_out);
        } while (z.avail_out == 0 || (last && status != Z_STREAM_END));
    }
    deflateEnd(&z);
    std::string png("\x89PNG\r\n\x1a\n", 8);
    appendChunk(png, "IHDR", header);
    appendChunk(png, "IDAT", compressed);
    appendChunk(png, "IEND", "");
    std::ofstream(file, std::ios::binary).write(png.data(), static_cast<std::streamsize>(png.size()));
    return true;
}

}  // namespace toyhost::testing
