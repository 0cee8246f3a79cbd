#include "session/BackgroundWriter.h"

namespace toyhost {

BackgroundWriter::BackgroundWriter() : thread_([this] { loop(); }) {}

BackgroundWriter::~BackgroundWriter() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void BackgroundWriter::submit(Job job) {
    {
        std::lock_guard lock(mutex_);
        jobs_.push_back(std::move(job));
    }
    changed_.notify_all();
}

void BackgroundWriter::drain() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return jobs_.empty() && running_ == 0; });
}

std::vector<Result<std::filesystem::path>> BackgroundWriter::takeFinished() {
    std::lock_guard lock(mutex_);
    std::vector<Result<std::filesystem::path>> out;
    out.swap(finished_);
    return out;
}

void BackgroundWriter::loop() {
    std::unique_lock lock(mutex_);
    while (true) {
        changed_.wait(lock, [&] { return stopping_ || !jobs_.empty(); });
        if (jobs_.empty()) return;  // stopping, and nothing left
        Job job = std::move(jobs_.front());
        jobs_.pop_front();
        ++running_;
        lock.unlock();
        Result<std::filesystem::path> result = job();
        lock.lock();
        --running_;
        finished_.push_back(std::move(result));
        changed_.notify_all();
    }
}

}  // namespace toyhost
