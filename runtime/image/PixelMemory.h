// PixelMemory: image-sized buffers for inputs allocated without letting std::bad_alloc escape, and
// the error that says how much a picture asked for ("needs 1.00 GiB for 16384x16384 RGBA"). No GL.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "core/ByteText.h"
#include "core/Result.h"

namespace toyhost {

// Sizes `buffer` to `bytes`; false (the buffer left empty) when that memory cannot be had.
bool tryResize(std::vector<std::uint8_t>& buffer, std::size_t bytes) noexcept;

// "1.00 GiB for 16384x16384 RGBA" (`count` pictures: "1.50 GiB for 6 faces of 8192x8192 RGBA").
std::string pictureMemoryText(int width, int height, int count = 1, const std::string& of = "");

// The error for a buffer of an input that could not be allocated: "not enough memory: WHAT needs
// NEEDS" (the ImageTooLarge code: the picture is too large for the memory toyhost could get).
Error notEnoughMemory(const std::string& file, const std::string& what, const std::string& needs);

}  // namespace toyhost
