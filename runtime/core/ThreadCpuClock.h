// ThreadCpuClock: the CPU time of the calling thread as a std::chrono clock, for limits on work
// that one thread does (decoding an image): time the thread waits for a core on a loaded machine,
// or spends suspended (SIGSTOP, Ctrl-Z), does not count. No GL.
#pragma once

#include <chrono>
#include <ctime>

namespace toyhost {

struct ThreadCpuClock {
    using duration = std::chrono::nanoseconds;
    using rep = duration::rep;
    using period = duration::period;
    using time_point = std::chrono::time_point<ThreadCpuClock>;
    static constexpr bool is_steady = true;

    static time_point now() noexcept {
        timespec t{};
        ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
        return time_point(duration(static_cast<rep>(t.tv_sec) * 1000000000 + t.tv_nsec));
    }
};

}  // namespace toyhost
