// GlWorker: the thread a Python session's GL work runs on. A GL context is current on one thread,
// while Python may call a session from any of its threads, so every call is handed to this one
// thread (toyhost's GL thread, with the large stack Mesa's compiler needs) and waited for. The
// caller releases the GIL while it waits. No GL context itself: the jobs make and use one.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <type_traits>

namespace toyhost::python {

class GlWorker {
public:
    GlWorker();
    ~GlWorker();  // stop()
    // Runs the jobs already handed over, then ends the thread and joins it (in the process that
    // made it): a closed session keeps no thread (nor its 1 GiB stack). Later jobs are not run.
    // Idempotent; not from a job.
    void stop();
    GlWorker(const GlWorker&) = delete;
    GlWorker& operator=(const GlWorker&) = delete;

    // Whether this is the process that made the worker: a fork() copies the worker's memory but
    // not its thread, so in a child the jobs would wait forever.
    bool inOwnProcess() const;

    // Runs `job` on the worker thread and returns its result (or rethrows what it threw). Jobs run
    // one at a time, in the order they were handed over. Must not be called from a job, nor where
    // inOwnProcess() is false; after stop() it throws std::logic_error.
    template <class Job>
    auto call(Job job) -> std::invoke_result_t<Job&> {
        using Value = std::invoke_result_t<Job&>;
        auto task = std::make_shared<std::packaged_task<Value()>>(std::move(job));
        std::future<Value> done = task->get_future();
        if (!post([task] { (*task)(); })) throw std::logic_error("the GL thread was stopped (the session is closed)");
        const auto until = std::chrono::steady_clock::now() + kSpin;
        while (done.wait_for(std::chrono::seconds(0)) != std::future_status::ready &&
               std::chrono::steady_clock::now() < until)
            std::this_thread::yield();
        return done.get();
    }

    // Hands `job` over without waiting for it (it runs after the jobs handed over before it). The
    // job must not throw. Same conditions as call(); after stop() the job is dropped (false).
    bool post(std::function<void()> job);

    // How long either side looks for the other's answer (yielding the core) before sleeping on
    // it. A wake-up from sleep costs tens of microseconds on an idle virtual machine, twice per
    // call; step(); frame() on a trivial 320x180 shader measured 0.28 ms/frame with 30 us against
    // 0.34-0.39 without (the CLI: 0.36-0.39), the ocean unchanged (docs/performance.md).
    static constexpr std::chrono::microseconds kSpin{50};

private:
    std::atomic<int> pending_{0};
    void serve();

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::function<void()>> jobs_;
    bool stopping_ = false;
    int process_ = 0;  // getpid() at creation
    std::thread thread_;
};

}  // namespace toyhost::python
