// Watchdog: makes sure a run ends when it must, even while the render thread is stuck in GL (which
// cannot be interrupted). A thread watches what the render thread publishes (core/RunActivity.h)
// against the limits: a pass compiling or drawing one frame too long, the encoders taking no frame
// (a stalled ffmpeg, also while the last frames are written). It also receives stop requests:
// SIGINT/SIGTERM (session/StopSignals.h), a window's Esc, an API call. A stop is acknowledged at
// once and the session stops before its next frame; if it has not ended within the grace period,
// or at a second signal, or when a limit passes, the run "expires": the expire callback decides
// what that means (the CLI removes unfinished files, stops child processes and ends the process
// with 124 or 128 + signal; a program that embeds toyhost may only record it). Every limit counts
// the time the process ran: a suspension (SIGSTOP, Ctrl-Z) is not a runaway frame. No GL needed.
#pragma once

#include <atomic>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>

#include "core/Defaults.h"
#include "core/Diagnostic.h"
#include "core/FileDescriptor.h"
#include "core/PauseLedger.h"
#include "core/RunActivity.h"

namespace toyhost {

enum class StopReason {
    None,
    Signal,   // SIGINT / SIGTERM: the run ends as interrupted (exit 128 + signal)
    Quit,     // the user closed the window (Esc, Ctrl+Q, the close button): outputs are completed
    Request,  // SessionCore::requestStop from a program: the run ends as interrupted
};

struct StopState {
    StopReason reason = StopReason::None;
    int signal = 0;  // with Signal
};

struct WatchdogDesc {
    double frameLimit = 0;    // seconds a pass may draw one frame, or the encoders take no frame; 0: off
    double compileLimit = 0;  // seconds one pass may compile; 0: off
    double graceSeconds = defaults::kStopGraceSeconds;
    bool watchSignals = false;  // read session/StopSignals.h's pipe (installStopSignals first)
    // Called on the watchdog's thread when a stop is asked for ("SIGTERM: stopping before the next
    // frame (again to stop at once)"); may be empty.
    std::function<void(const Diagnostic&)> acknowledge;
    // Called on the watchdog's thread when the run must end now (see above) with the exit code a
    // process should end with: 124 for a limit, 128 + signal, 130 for a quit that could not
    // finish. Empty: the expiry is only recorded (expired()) and a stop is requested.
    std::function<void(const Diagnostic&, int exitCode)> expire;
};

inline constexpr int kExitWatchdog = 124;  // as timeout(1) ends

class Watchdog {
public:
    explicit Watchdog(WatchdogDesc desc);
    ~Watchdog();  // stops its thread
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    // Where the render thread publishes what it does.
    RunActivity& activity() { return activity_; }
    // True when draws must be followed (a frame limit is set).
    bool watchesDraws() const { return desc_.frameLimit > 0; }

    // Asks the run to stop (any thread); the first request counts, a second signal expires at once.
    void requestStop(StopReason reason, int signal = 0);
    StopState stop() const;
    // The render thread saw a Quit and now completes the outputs: the grace period no longer
    // applies (a signal's does: its run only abandons what is unfinished).
    void quitHonoured();
    // The window was closed again while its quit is being honoured: the run expires at once, as
    // after a second signal (exit 130, unfinished files removed). Nothing when no quit is under way.
    void quitAgain();
    bool stopRequested() const { return stopped_.load(std::memory_order_acquire); }
    // The expiry, when the expire callback did not end the process.
    std::optional<Diagnostic> expired() const;

private:
    void loop();
    void expireWith(Diagnostic diagnostic, int exitCode);
    void acknowledgeSignal(int signal);

    WatchdogDesc desc_;
    RunActivity activity_;
    mutable std::mutex mutex_;
    StopState stop_;
    std::chrono::steady_clock::time_point stopAt_;
    bool graceArmed_ = false;
    std::atomic<bool> stopped_{false};
    int signals_ = 0;  // watchdog thread only
    PauseLedger pauses_;  // watchdog thread only
    std::optional<Diagnostic> expired_;
    CancelSignal done_;
    std::thread thread_;
};

// A session's one stop state: its watchdog's, which signals and limits set too, when it has one;
// else a request kept here (a session without limits, as the GL tests make). Any thread.
class SessionStop {
public:
    explicit SessionStop(Watchdog* watchdog) : watchdog_(watchdog) {}
    void request(StopReason reason) {
        if (watchdog_) watchdog_->requestStop(reason);
        else local_.store(static_cast<int>(reason));
    }
    bool requested() const {
        return watchdog_ ? watchdog_->stopRequested() : local_.load() != static_cast<int>(StopReason::None);
    }
    // A stop that means "the user closed the window": the run ends as complete.
    bool quitRequested() {
        if (!watchdog_) return local_.load() == static_cast<int>(StopReason::Quit);
        if (watchdog_->stop().reason != StopReason::Quit) return false;
        watchdog_->quitHonoured();
        return true;
    }

private:
    Watchdog* watchdog_;
    std::atomic<int> local_{0};
};

}  // namespace toyhost
