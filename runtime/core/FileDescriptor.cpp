#include "core/FileDescriptor.h"

#include <cerrno>
#include <cstring>
#include <unistd.h>

namespace toyhost {

bool FileDescriptor::reset() {
    if (fd_ < 0) return true;
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0;
}

Status writeAll(int fd, std::span<const std::byte> bytes, const std::string& what) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0) {
            if (errno == EINTR) continue;
            if (errno == EPIPE) return Error{what + ": the reading end was closed (broken pipe)"};
            return Error{what + ": write failed: " + std::strerror(errno)};
        }
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    return okStatus();
}

}  // namespace toyhost
