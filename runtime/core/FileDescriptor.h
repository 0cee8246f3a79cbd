// FileDescriptor: RAII owner of a POSIX file descriptor, and writing a whole byte range to one
// (pipes and stdout take partial writes). No GL needed.
#pragma once

#include <csignal>
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

// A one-way "stop now" flag that another thread can wait on with poll(): cancel() wakes every
// writeAll() waiting on a pipe that nobody reads, so a stalled reader cannot hold a thread
// forever. Thread-safe.
class CancelSignal {
public:
    CancelSignal();
    void cancel();
    bool cancelled() const;
    int pollFd() const { return fd_.get(); }  // readable once cancelled

private:
    FileDescriptor fd_;  // an eventfd
};

// Blocks SIGPIPE on the calling thread while it lives, for writes to a pipe on a thread that does
// not block it for good (stdout of the sound command, the capture's synchronous path): a closed
// pipe must give EPIPE, not end the process. A SIGPIPE raised meanwhile is consumed before the old
// mask comes back, so it is never delivered.
class PipeSignalBlock {
public:
    PipeSignalBlock();
    ~PipeSignalBlock();
    PipeSignalBlock(const PipeSignalBlock&) = delete;
    PipeSignalBlock& operator=(const PipeSignalBlock&) = delete;

private:
    sigset_t pipe_{}, previous_{};
    bool wasPending_ = false;
};

// Writes every byte, retrying partial writes and EINTR. `what` names the destination in errors
// ("stdout", "ffmpeg's input"). A closed pipe gives EPIPE (the caller blocks SIGPIPE). With a
// `cancel` signal, writes to a pipe never block past a cancel(): they wait in poll() and write
// only what the pipe can take, and end with a "cancelled" error.
Status writeAll(int fd, std::span<const std::byte> bytes, const std::string& what,
                const CancelSignal* cancel = nullptr);

}  // namespace toyhost
