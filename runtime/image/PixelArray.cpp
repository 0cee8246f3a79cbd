#include "image/PixelArray.h"

namespace toyhost {

std::string describePixelArray(const PixelArray& a) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "(" + std::string.
    std::string text = "(";
    text += std::to_string(a.height);
    text += ", ";
    text += std::to_string(a.width);
    text += ", ";
    text += std::to_string(a.components);
    text += ") ";
    text += a.type == PixelType::UInt8 ? "uint8" : "float32";
    return text;
}

Status checkPixelArray(const PixelArray& a, int maxSide, const std::string& what) {
    if (a.width < 1 || a.height < 1 || a.width > maxSide || a.height > maxSide)
        return Error(what + ": an array of " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                         " pixels; each side must be 1.." + std::to_string(maxSide),
                     Code::Usage);
    if (a.components != 1 && a.components != 3 && a.components != 4)
        return Error(what + ": " + std::to_string(a.components) +
                         " components per pixel; a channel takes 1 (R), 3 (RGB) or 4 (RGBA)",
                     Code::Usage);
    if (!a.data) return Error(what + ": no pixel data", Code::Usage);
    const std::size_t expected = rowBytes(a) * static_cast<std::size_t>(a.height);
    if (a.bytes != expected)
        return Error(what + ": " + std::to_string(a.bytes) + " bytes for an array of shape " + describePixelArray(a) +
                         ", which needs " + std::to_string(expected),
                     Code::Usage);
    return okStatus();
}

}  // namespace toyhost
