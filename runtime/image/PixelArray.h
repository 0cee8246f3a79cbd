// PixelArray: pixels a program hands toyhost to show in a channel (a numpy array, a video frame,
// a simulation's field): their shape, type and row order, and the checks they must pass before
// anything is uploaded. Plain data and arithmetic; no GL needed.
#pragma once

#include <cstddef>
#include <string>

#include "core/Result.h"

namespace toyhost {

enum class PixelType { UInt8, Float32 };

struct PixelArray {
    int width = 0;
    int height = 0;
    int components = 4;  // 1 (R), 3 (RGB) or 4 (RGBA)
    PixelType type = PixelType::UInt8;
    const void* data = nullptr;  // width * height * components values, rows packed
    std::size_t bytes = 0;       // what `data` holds, checked against the shape
    bool topRowFirst = true;     // row 0 is the picture's top (shown at t = 1), as images are read
};

inline std::size_t valueBytes(PixelType type) { return type == PixelType::UInt8 ? 1 : 4; }
inline std::size_t rowBytes(const PixelArray& a) {
    return static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.components) * valueBytes(a.type);
}

// The shape as messages write it: "(180, 320, 3) float32".
std::string describePixelArray(const PixelArray& array);

// Refuses (Code::Usage, naming `what`) a size outside 1..maxSide, a component count other than
// 1, 3 or 4, no data, or a byte count that does not match the shape.
Status checkPixelArray(const PixelArray& array, int maxSide, const std::string& what);

}  // namespace toyhost
