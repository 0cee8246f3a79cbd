#include "image/PixelMemory.h"

#include <new>
#include <stdexcept>

namespace toyhost {

bool tryResize(std::vector<std::uint8_t>& buffer, std::size_t bytes) noexcept {
    try {
        buffer.resize(bytes);
        return true;
    } catch (const std::bad_alloc&) {
    } catch (const std::length_error&) {
    }
    std::vector<std::uint8_t>().swap(buffer);
    return false;
}

std::string pictureMemoryText(int width, int height, int count, const std::string& of) {
    const std::uint64_t bytes = std::uint64_t(width) * std::uint64_t(height) * 4 * std::uint64_t(count);
    const std::string size = std::to_string(width) + "x" + std::to_string(height) + " RGBA";
    return formatBytes(bytes) + " for " + (count > 1 ? std::to_string(count) + " " + of + " of " : "") + size;
}

Error notEnoughMemory(const std::string& file, const std::string& what, const std::string& needs) {
    return fileError(file, "not enough memory: " + what + " needs " + needs, Code::ImageTooLarge);
}

}  // namespace toyhost
