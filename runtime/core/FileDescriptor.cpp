#include "core/FileDescriptor.h"

#include <pthread.h>
#include <ctime>

#include <cerrno>
#include <cstring>
#include <algorithm>
#include <cstdint>
#include <fcntl.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <unistd.h>

namespace toyhost {

bool FileDescriptor::reset() {
    if (fd_ < 0) return true;
    const int result = ::close(fd_);
    fd_ = -1;
    return result == 0;
}

CancelSignal::CancelSignal() : fd_(::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK)) {}

void CancelSignal::cancel() {
    const std::uint64_t one = 1;
    if (fd_) (void)!::write(fd_.get(), &one, sizeof one);
}

bool CancelSignal::cancelled() const {
    pollfd p{fd_.get(), POLLIN, 0};
    return fd_ && ::poll(&p, 1, 0) == 1;
}

PipeSignalBlock::PipeSignalBlock() {
    sigemptyset(&pipe_);
    sigaddset(&pipe_, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    wasPending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &pipe_, &previous_);
}

PipeSignalBlock::~PipeSignalBlock() {
    sigset_t pending;
    sigpending(&pending);
    if (!wasPending_ && sigismember(&pending, SIGPIPE) == 1) {
        const timespec now{};
        sigtimedwait(&pipe_, nullptr, &now);
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
}

namespace {

Error writeError(const std::string& what, int error) {
    if (error == EPIPE) return Error(what + ": the reading end was closed (broken pipe)", Code::IoBrokenPipe);
    return Error(what + ": write failed: " + std::strerror(error), error == ENOSPC ? Code::IoNoSpace : Code::IoWrite);
}

// Bytes a write to pipe `fd` can take without blocking, or -1 when `fd` is not a pipe.
long pipeRoom(int fd) {
    const int capacity = ::fcntl(fd, F_GETPIPE_SZ);
    if (capacity < 0) return -1;
    int queued = 0;
    if (::ioctl(fd, FIONREAD, &queued) != 0) return -1;
    return static_cast<long>(capacity) - queued;
}

}  // namespace

Status writeAll(int fd, std::span<const std::byte> bytes, const std::string& what, const CancelSignal* cancel) {
    while (!bytes.empty()) {
        std::size_t chunk = bytes.size();
        if (cancel) {
            // Wait until the destination takes bytes, or the cancel signal fires.
            pollfd wait[2] = {{fd, POLLOUT, 0}, {cancel->pollFd(), POLLIN, 0}};
            if (::poll(wait, 2, -1) < 0) {
                if (errno == EINTR) continue;
                return writeError(what, errno);
            }
            if (wait[1].revents & POLLIN) return Error(what + ": writing was cancelled", Code::Cancelled);
            // A pipe with some room still blocks a write larger than that room; write only what fits.
            const long room = pipeRoom(fd);
            if (room == 0) continue;
            if (room > 0) chunk = std::min(chunk, static_cast<std::size_t>(room));
        }
        const ssize_t n = ::write(fd, bytes.data(), chunk);
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return writeError(what, errno);
        }
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    return okStatus();
}

}  // namespace toyhost
