// GlThread: what a program that renders with toyhost sets up once, before any other thread exists:
// the EGL platform TOYHOST_EGL_PLATFORM asks for, and standard streams that are really open (a
// closed fd 1 would otherwise be reused by toyhost's own pipes, and raw frames for stdout would go
// into them); then the thread every GL call runs on, with a stack large
// enough for Mesa's recursive GLSL compiler. Every command and the compatibility runner use it.
// No GL context needed (it makes none).
#pragma once

#include <array>
#include <chrono>
#include <exception>
#include <functional>
#include <pthread.h>

#include <toyhost/Export.h>

#include "core/Result.h"
#include "gl/HeadlessContext.h"

namespace toyhost {

struct GlProcess {
    EglPlatform eglPlatform = EglPlatform::Automatic;  // from TOYHOST_EGL_PLATFORM
    // Standard streams (0, 1, 2) that were closed when the process started; each is now /dev/null
    // opened so that writes fail (EBADF) instead of landing in a pipe that took its number.
    std::array<bool, 3> closedAtStart{};
    // When the process started (as near as prepareGlProcess knows), for start-up times in reports.
    std::chrono::steady_clock::time_point startedAt = std::chrono::steady_clock::now();
};

// Call once, first thing in main(), before any thread starts. Errors: a TOYHOST_EGL_PLATFORM that
// is not surfaceless, device or automatic (a usage error).
Result<GlProcess> prepareGlProcess();

// The stack of the GL thread: Mesa's GLSL compiler recurses once per statement of a long
// function, so a large shader that compiles on the site overflows the usual 8 MiB and ends the
// process with no message. Address space only: pages are used as they are touched.
inline constexpr std::size_t kGlThreadStackBytes = std::size_t(1) << 30;

// A thread with kGlThreadStackBytes of stack running `job` (on the calling thread, at join(), if
// such a thread cannot be made).
class GlThread {
public:
    explicit GlThread(std::function<void()> job);
    ~GlThread();  // joins
    GlThread(const GlThread&) = delete;
    GlThread& operator=(const GlThread&) = delete;
    // Waits for the job; an exception it threw (bad_alloc) is thrown again here, on the caller's
    // thread, instead of ending the process from the GL thread.
    void join();

private:
    void run();

    std::function<void()> job_;
    std::exception_ptr failure_;
    pthread_t thread_{};
    bool started_ = false;
    bool joined_ = false;
};

// Runs `job` on a GlThread and waits for it. Part of the public API too (toyhost/Session.h), so
// libtoyhost.so exports it.
TOYHOST_API void runOnGlThread(const std::function<void()>& job);

}  // namespace toyhost
