// StopWatcher: the CLI's watcher thread, which makes sure a run ends when it must even while the
// render thread is stuck in GL (which cannot be interrupted): a signal is acknowledged at once;
// if the run has not stopped within the grace period, or at a second signal, every unfinished
// file is removed, every child process killed (core/InFlight.h) and the process exits 130/143.
// As the watchdog it ends a frame or a shader compilation that outlives its limit (exit 124),
// naming the pass, from what the render thread publishes (core/RunActivity.h).
#pragma once

#include <atomic>
#include <thread>

#include "core/FileDescriptor.h"
#include "core/RunActivity.h"

namespace toyhost::cli {

inline constexpr int kExitTimeout = 124;  // the watchdog ended the run (as timeout(1) does)

class StopWatcher {
public:
    // Limits in seconds; 0 turns one off. Needs installStopSignals() first.
    StopWatcher(double frameLimit, double compileLimit, double graceSeconds);
    ~StopWatcher();  // stops the thread
    StopWatcher(const StopWatcher&) = delete;
    StopWatcher& operator=(const StopWatcher&) = delete;

    // What the run publishes; nullptr when no limit is set (nothing to watch).
    RunActivity* activity() { return frameLimit_ > 0 || compileLimit_ > 0 ? &activity_ : nullptr; }

private:
    void loop();
    [[noreturn]] void endNow(int exitCode, const char* why);

    double frameLimit_, compileLimit_, grace_;
    RunActivity activity_;
    CancelSignal done_;
    std::thread thread_;
};

}  // namespace toyhost::cli
