#include "capture/SoundEncoding.h"

#include <algorithm>
#include <cmath>

namespace toyhost {

namespace {
// The shader's v = floor((0.5 + 0.5*x) * 65536.0), in float like a GPU's highp.
float shaderValue(float x) {
    const float scaled = (0.5f + 0.5f * x) * 65536.0f;
    return std::floor(scaled);
}

// A value in 0..1 as the RGBA8 store turns it into a byte (round to nearest after clamping).
std::uint8_t unormByte(float value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}
}  // namespace

std::uint16_t soundCode(float x) {
    if (std::isnan(x)) return 0;
    return static_cast<std::uint16_t>(std::clamp(shaderValue(x), 0.0f, 65535.0f));
}

SoundBytes soundBytes(float x) {
    if (std::isnan(x)) return {};
    const float v = shaderValue(x);
    if (std::isinf(v)) return v > 0 ? SoundBytes{0, 255} : SoundBytes{0, 0};
    // GLSL mod(a, b) = a - b*floor(a/b): never negative for b > 0.
    const float lo = v - 256.0f * std::floor(v / 256.0f);
    const float hi = std::floor(v / 256.0f);
    return {unormByte(lo / 255.0f), unormByte(hi / 255.0f)};
}

float decodeSoundSample(std::uint8_t lo, std::uint8_t hi) {
    return static_cast<float>(-1.0 + 2.0 * (lo + 256.0 * hi) / 65535.0);
}

void decodeSoundBlock(std::span<const std::uint8_t> rgba, std::span<float> stereoOut) {
    const std::size_t samples = std::min(rgba.size() / 4, stereoOut.size() / 2);
    for (std::size_t i = 0; i < samples; ++i) {
        stereoOut[2 * i] = decodeSoundSample(rgba[4 * i], rgba[4 * i + 1]);
        stereoOut[2 * i + 1] = decodeSoundSample(rgba[4 * i + 2], rgba[4 * i + 3]);
    }
}

}  // namespace toyhost
