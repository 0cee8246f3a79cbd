// GlWorker: a queue of jobs served by one thread that runs inside toyhost::runOnGlThread.
#include "GlWorker.h"

#include <toyhost/Session.h>

namespace toyhost::python {

GlWorker::GlWorker() {
    // runOnGlThread gives the large stack (the public API's one place for its size); the std::thread
    // around it only waits for it.
    thread_ = std::thread([this] { runOnGlThread([this] { serve(); }); });
}

GlWorker::~GlWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
}

void GlWorker::post(std::function<void()> job) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    wake_.notify_one();
}

void GlWorker::serve() {
    for (;;) {
        std::function<void()> job;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !jobs_.empty(); });
            if (jobs_.empty()) return;  // stopping, and nothing left to do
            job = std::move(jobs_.front());
            jobs_.pop_front();
        }
        job();
    }
}

}  // namespace toyhost::python
