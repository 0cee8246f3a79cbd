// FileDescriptor: RAII owner of a POSIX file descriptor, and writing a whole byte range to one
// (pipes and stdout take partial writes). No GL needed.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <utility>

#include "core/Result.h"

namespace toyhost {

class FileDescriptor {
public:
    FileDescriptor() = default;
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() { reset(); }
    FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    FileDescriptor& operator=(FileDescriptor&& other) noexcept {
        if (this != &other) {
            reset();
            fd_ = std::exchange(other.fd_, -1);
        }
        return *this;
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;

    int get() const { return fd_; }
    explicit operator bool() const { return fd_ >= 0; }
    // Closes now; returns false when close() reported an error (a lost write).
    bool reset();

private:
    int fd_ = -1;
};

// Writes every byte, retrying partial writes and EINTR. `what` names the destination in errors
// ("stdout", "ffmpeg's input"). A closed pipe gives EPIPE (the caller blocks SIGPIPE).
Status writeAll(int fd, std::span<const std::byte> bytes, const std::string& what);

}  // namespace toyhost
