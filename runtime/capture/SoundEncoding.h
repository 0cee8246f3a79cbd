// SoundEncoding: the arithmetic of Shadertoy's Sound pass, which renders mainSound() into 512x512
// RGBA8 blocks of 262144 samples and reads them back as 16-bit codes split over two bytes per
// channel. Pure arithmetic, no GL needed.
//
// The site's shader footer writes, per channel, v = floor((0.5 + 0.5*x) * 65536.0) as
// vec4(mod(v.x,256)/255, floor(v.x/256)/255, mod(v.y,256)/255, floor(v.y/256)/255), and the player
// decodes each channel as -1 + 2*(lo + 256*hi)/65535 into a Float32Array (effect.js,
// Create_Sound / Paint_Sound, read in public mirrors). The RGBA8 target clamps each stored value
// to 0..1, so x = 1.0 (v = 65536) stores lo = 0 and hi = 256/255 -> 255: the site plays 65280,
// i.e. 0.992218, not 1. Values checked in tests/io/test_wav_file.cpp:
//   x = -1 -> lo 0, hi 0   -> -1
//   x =  0 -> lo 0, hi 128 -> -1 + 65536/65535 = 1.5259e-5
//   x = .5 -> lo 0, hi 192 -> -1 + 98304/65535 = 0.500023
//   x =  1 -> lo 0, hi 255 -> -1 + 130560/65535 = 0.992218
#pragma once

#include <cstdint>
#include <span>

namespace toyhost {

inline constexpr int kSoundBlockSide = 512;
inline constexpr int kSoundBlockSamples = kSoundBlockSide * kSoundBlockSide;  // 262144

// The two bytes the RGBA8 target holds for one channel's value.
struct SoundBytes {
    std::uint8_t lo = 0;
    std::uint8_t hi = 0;
};

// The shader's v for x (computed in 32-bit float as the GPU does), clamped to 0..65535: the
// 16-bit code x was meant to become. NaN gives 0.
std::uint16_t soundCode(float x);

// What the RGBA8 target really stores for x: lo = mod(v, 256) and hi = floor(v / 256), each
// clamped to 0..255 by the unsigned-normalized store. Differs from soundCode's bytes where v is
// outside 0..65535 (x >= 1 wraps lo to 0; x < -1 keeps lo = mod(v, 256)). NaN gives {0, 0}.
SoundBytes soundBytes(float x);

// The player's decoding of one channel: -1 + 2*(lo + 256*hi)/65535, computed in double and
// stored as float, as the site's Float32Array does.
float decodeSoundSample(std::uint8_t lo, std::uint8_t hi);

// Decodes a block read back from the Sound target: `rgba` is 4 bytes per sample in reading
// order (glReadPixels' row 0 = the first 512 samples; R,G = left lo/hi, B,A = right lo/hi),
// `stereoOut` receives interleaved left/right floats. Decodes min(rgba.size()/4,
// stereoOut.size()/2) samples; the rest of `stereoOut` is left as it was.
void decodeSoundBlock(std::span<const std::uint8_t> rgba, std::span<float> stereoOut);

}  // namespace toyhost
