// VolumeFile: Shadertoy's volume textures (ctype `volume`, sampled as sampler3D): reading the
// site's `.bin` files and deterministic stand-ins for the stock ones. CPU only, no GL needed.
//
// The format, as the site's effect.js reads it (EffectPass.NewTexture, case "volume", read in
// public mirrors of effect.js/piLibs.js): a 20-byte little-endian header
//   uint32 signature, uint32 x size, uint32 y size, uint32 z size,
//   uint8 channel count, uint8 layout, uint16 format (0 = 8-bit unsigned, 10 = 32-bit float),
// then the voxels from byte 20 on, handed unchanged to texImage3D: x fastest, then y, then z,
// nothing flipped (WebGL ignores UNPACK_FLIP_Y for array data in 3D uploads). The site reads the
// signature and never checks it, and no public copy of a stock file could be read to learn its
// value, so any signature is accepted here as well. `layout` is read and ignored, as the site
// does. Note: the site's piRenderer passes the y size as the texture's depth too (it uploads
// x*y*y), which only matters for non-cubic volumes; the stock ones are 32x32x32 cubes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/Result.h"

namespace toyhost {

// 8 bits per channel; voxel (x, y, z) channel c is
// voxels[((z * height + y) * width + x) * channels + c], the file's order and GL's.
struct Volume8 {
    int width = 0;
    int height = 0;
    int depth = 0;
    int channels = 0;  // 1..4
    // Format 10: each value is a little-endian 32-bit float (4 bytes in `voxels`); else a byte.
    bool floats = false;
    std::vector<std::uint8_t> voxels;
};

// Limits on what a volume file may declare: every side at most kMaxVolumeSide, the voxel data at
// most kMaxVolumeBytes (the stock volumes are 32 KiB and 128 KiB).
inline constexpr int kMaxVolumeSide = 1024;
inline constexpr std::uint64_t kMaxVolumeBytes = std::uint64_t(256) << 20;
inline constexpr std::size_t kVolumeHeaderBytes = 20;

// Reads an 8-bit volume file. Errors (code Code::VolumeDecode, naming the file): shorter than the
// header, a zero side, a side over kMaxVolumeSide or data over kMaxVolumeBytes, a channel count
// not 1..4, a format other than 0 (8-bit) or 10 (32-bit float, as the site also reads), and voxel
// data shorter or longer than the header says. A missing file or a folder gets the I/O error.
Result<Volume8> readVolumeFile(const std::filesystem::path& path);

// The file's bytes for `volume` (signature 0, which the site never checks; layout 0; format 0),
// for tests and tools.
std::vector<std::uint8_t> encodeVolumeFile(const Volume8& volume);

// A side^3 volume of uniform random bytes, the same on every run and machine for a given seed
// (splitmix64): what the stock "Grey Noise3D" (32^3, 1 channel) and "RGBA Noise3D" (32^3,
// 4 channels) are. `side` is clamped to 1..kMaxVolumeSide (and to the byte limit), `channels`
// to 1..4.
Volume8 volumeStandIn(int side, int channels, std::uint32_t seed);

}  // namespace toyhost
