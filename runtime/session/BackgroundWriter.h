// BackgroundWriter: the files a session writes besides captured frames (screenshots, checkpoints,
// a video's sound track) are written on a thread of their own, so that no file I/O happens on the
// GL thread. Jobs run one at a time, in order; each finished job leaves its result (the file it
// wrote, or its error) for the session to report on its own thread. No GL needed.
#pragma once

#include <condition_variable>
#include <deque>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "core/Result.h"

namespace toyhost {

class BackgroundWriter {
public:
    using Job = std::function<Result<std::filesystem::path>()>;

    BackgroundWriter();
    ~BackgroundWriter();  // runs the jobs still queued, then stops
    BackgroundWriter(const BackgroundWriter&) = delete;
    BackgroundWriter& operator=(const BackgroundWriter&) = delete;

    void submit(Job job);
    // Waits until every job submitted so far has run.
    void drain();
    // The results of the jobs that finished since the last call, in order.
    std::vector<Result<std::filesystem::path>> takeFinished();

private:
    void loop();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Job> jobs_;
    std::vector<Result<std::filesystem::path>> finished_;
    int running_ = 0;
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace toyhost
