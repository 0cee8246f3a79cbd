// GlWorker: a queue of jobs served by one thread that runs inside toyhost::runOnGlThread.
#include "GlWorker.h"

#include <unistd.h>

#include <chrono>

#include <toyhost/Session.h>

namespace toyhost::python {

GlWorker::GlWorker() : process_(static_cast<int>(::getpid())) {
    // runOnGlThread gives the large stack (the public API's one place for its size); the std::thread
    // around it only waits for it.
    thread_ = std::thread([this] { runOnGlThread([this] { serve(); }); });
}

bool GlWorker::inOwnProcess() const { return static_cast<int>(::getpid()) == process_; }

GlWorker::~GlWorker() { stop(); }

void GlWorker::stop() {
    if (!thread_.joinable()) return;
    if (!inOwnProcess()) {
        // A forked child's copy: the thread is the parent's; nothing here can stop or join it.
        thread_.detach();
        return;
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

bool GlWorker::post(std::function<void()> job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return false;
        jobs_.push_back(std::move(job));
        pending_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_one();
    return true;
}

void GlWorker::serve() {
    for (;;) {
        std::function<void()> job;
        {
            // A caller usually hands the next job over within microseconds (step() then frame()):
            // look for it briefly before sleeping, so that it needs no wake-up.
            const auto until = std::chrono::steady_clock::now() + kSpin;
            while (pending_.load(std::memory_order_acquire) == 0 && std::chrono::steady_clock::now() < until)
                std::this_thread::yield();
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            if (jobs_.empty()) return;  // stopping, and nothing left to do
            job = std::move(jobs_.front());
            jobs_.pop_front();
            pending_.fetch_sub(1, std::memory_order_release);
        }
        job();
    }
}

}  // namespace toyhost::python
