#include "gl/GlThread.h"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <utility>

namespace toyhost {

Result<GlProcess> prepareGlProcess() {
    GlProcess process;
    for (int fd = 0; fd < 3; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1) continue;
        // Read-only /dev/null for an output stream: writing to it fails with EBADF, which the
        // writer reports ("stdout: write failed"), and nothing else can take the number.
        const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_RDONLY);
        if (opened >= 0 && opened != fd) {
            ::dup2(opened, fd);
            ::close(opened);
        }
        process.closedAtStart[fd] = true;
    }
    Result<EglPlatform> platform = eglPlatformFromEnvironment();
    if (!platform) return platform.error();
    process.eglPlatform = *platform;
    return process;
}

GlThread::GlThread(std::function<void()> job) : job_(std::move(job)) {
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    pthread_attr_setstacksize(&attributes, kGlThreadStackBytes);
    auto start = [](void* self) -> void* {
        static_cast<GlThread*>(self)->run();
        return nullptr;
    };
    started_ = pthread_create(&thread_, &attributes, start, this) == 0;
    pthread_attr_destroy(&attributes);
}

GlThread::~GlThread() {
    try {
        join();
    } catch (...) {  // a destructor does not throw: the job's failure was for join() to give
    }
}

void GlThread::run() {
    try {
        job_();
    } catch (...) {
        failure_ = std::current_exception();
    }
}

void GlThread::join() {
    if (joined_) return;
    joined_ = true;
    if (started_) pthread_join(thread_, nullptr);
    else run();
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
}

void runOnGlThread(const std::function<void()>& job) {
    GlThread thread(job);
    thread.join();
}

}  // namespace toyhost
