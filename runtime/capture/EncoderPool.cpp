#include "capture/EncoderPool.h"

#include "core/FileDescriptor.h"

#include <algorithm>
#include <csignal>
#include <ctime>
#include <pthread.h>
#include <exception>
#include <system_error>

namespace toyhost {


int defaultEncoderThreads() {
    const int hardware = static_cast<int>(std::thread::hardware_concurrency());
    return std::max(1, hardware - 1);
}

int maxEncoderThreads() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

EncoderPool::EncoderPool(FrameSink& sink, int threads, std::size_t memoryCapBytes, int growTo)
    : sink_(sink), queue_(memoryCapBytes) {
    const int count = threads <= 0 ? 0 : (sink.ordered() ? 1 : threads);
    growTo_ = count > 0 && !sink.ordered() ? std::max(count, growTo) : count;
    workers_.reserve(static_cast<std::size_t>(growTo_));
    for (int i = 0; i < count; ++i) startWorker();
    if (static_cast<int>(workers_.size()) < count) growTo_ = static_cast<int>(workers_.size());  // refused: no growing
}

void EncoderPool::startWorker() {
    // A thread that cannot be started (too many asked for, a process limit) must not escape as an
    // exception past the ones already running (std::terminate): the pool keeps those, and with
    // none it is synchronous. threads() says how many it got.
    try {
        workers_.emplace_back([this] { work(); });
    } catch (const std::system_error&) {
        growTo_ = threads();
    }
}

void EncoderPool::growIfBehind() {
    // Called when the producer found no free buffer under the cap while frames still wait to be
    // taken: the encoders are behind rendering. One more thread.
    if (threads() >= growTo_ || threads() == 0) return;
    if (queue_.queuedFrames() > 0) startWorker();
}

EncoderPool::~EncoderPool() {
    if (!finished_) abandon();
}

void EncoderPool::abandon() {
    if (abandoned_ || finished_) return;
    abandoned_ = true;
    queue_.abort();
    // A thread blocked inside the sink (a reader that stopped reading, a stalled ffmpeg) is
    // released first, so joining it cannot hang the process.
    sink_.cancel();
    stop();
    sink_.discard();
}

void EncoderPool::work() {
    // A sink writing into a pipe whose reader died must see EPIPE, not kill the process with
    // SIGPIPE; the signal is thread-directed, so blocking it here is enough.
    sigset_t pipeSignal;
    sigemptyset(&pipeSignal);
    sigaddset(&pipeSignal, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipeSignal, nullptr);

    EncodeScratch scratch;
    while (std::optional<CapturedFrame> frame = queue_.pop()) {
        Status written = writeGuarded(*frame, scratch);
        if (written) ++framesWritten_;
        queue_.recycle(std::move(frame->pixels));
        if (!written) {
            fail(written.error());
            return;
        }
    }
}

Status EncoderPool::writeGuarded(const CapturedFrame& frame, EncodeScratch& scratch) {
    // An exception (bad_alloc, a codec library's own) must become the run's error: escaping a
    // thread it would call std::terminate and leave ffmpeg and temporary files behind.
    try {
        return sink_.write(frame, scratch);
    } catch (const std::exception& e) {
        return Error(std::string("capture: encoding frame ") + std::to_string(frame.frame) + " failed: " + e.what(),
                     Code::CaptureException);
    } catch (...) {
        return Error("capture: encoding frame " + std::to_string(frame.frame) + " failed with an unknown exception",
                     Code::CaptureException);
    }
}

void EncoderPool::fail(Error error) {
    {
        std::lock_guard lock(errorMutex_);
        if (!error_) error_ = std::move(error);
    }
    queue_.abort();  // wakes a producer blocked in acquire() so that it sees the error
}

std::optional<Error> EncoderPool::firstError() const {
    std::lock_guard lock(errorMutex_);
    return error_;
}

Result<std::vector<std::byte>> EncoderPool::acquire(std::size_t bytes, const std::function<bool()>& stop) {
    std::optional<std::vector<std::byte>> buffer = queue_.acquire(bytes, /*wait=*/false);
    if (!buffer) {
        growIfBehind();
        buffer = queue_.acquire(bytes, /*wait=*/true, stop);
    }
    if (!buffer) {
        if (std::optional<Error> error = firstError()) return *error;
        return Error(stop && stop() ? "capture: stopped while waiting for the encoders"
                                    : "capture: the encoder queue was stopped",
                     Code::CaptureStopped);
    }
    return std::move(*buffer);
}

Result<std::optional<std::vector<std::byte>>> EncoderPool::tryAcquire(std::size_t bytes) {
    if (std::optional<Error> error = firstError()) return *error;
    std::optional<std::vector<std::byte>> buffer = queue_.acquire(bytes, /*wait=*/false);
    if (!buffer) {
        if (std::optional<Error> error = firstError()) return *error;
    }
    return buffer;
}

Status EncoderPool::submit(CapturedFrame frame) {
    if (std::optional<Error> error = firstError()) return *error;
    if (workers_.empty()) {
        Status written = [&] {
            PipeSignalBlock noSigpipe;
            return writeGuarded(frame, inlineScratch_);
        }();
        if (written) ++framesWritten_;
        queue_.recycle(std::move(frame.pixels));
        if (!written) fail(written.error());
        return written;
    }
    queue_.push(std::move(frame));
    return okStatus();
}

void EncoderPool::stop() {
    for (std::thread& worker : workers_)
        if (worker.joinable()) worker.join();
}

Status EncoderPool::finish() {
    queue_.close();
    stop();
    if (std::optional<Error> error = firstError()) return *error;  // the destructor discards
    Status closed = sink_.close();
    if (!closed) return closed;
    finished_ = true;
    return okStatus();
}

}  // namespace toyhost
