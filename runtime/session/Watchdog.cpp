#include "session/Watchdog.h"

#include <cstdio>
#include <poll.h>
#include <string>
#include <unistd.h>

#include "session/StopSignals.h"

namespace toyhost {

namespace {
std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, s == static_cast<long long>(s) ? "%.0f" : "%.1f", s);
    return text;
}

Diagnostic problem(Code code, std::string message, const char* pass = "") {
    Diagnostic d;
    d.code = code;
    d.message = std::move(message);
    d.pass = pass;
    return d;
}
}  // namespace

namespace {
constexpr int kTickMilliseconds = 50;
}

Watchdog::Watchdog(WatchdogDesc desc)
    : desc_(std::move(desc)),
      pauses_(kTickMilliseconds / 1000.0, defaults::kSuspensionGapSeconds),
      thread_([this] { loop(); }) {}

Watchdog::~Watchdog() {
    done_.cancel();
    thread_.join();
}

void Watchdog::requestStop(StopReason reason, int signal) {
    std::lock_guard lock(mutex_);
    if (stop_.reason != StopReason::None) return;
    stop_ = {reason, signal};
    stopAt_ = std::chrono::steady_clock::now();
    graceArmed_ = true;
    stopped_.store(true, std::memory_order_release);
}

StopState Watchdog::stop() const {
    std::lock_guard lock(mutex_);
    return stop_;
}

void Watchdog::quitHonoured() {
    std::lock_guard lock(mutex_);
    if (stop_.reason == StopReason::Quit) graceArmed_ = false;
}

void Watchdog::quitAgain() {
    if (stop().reason != StopReason::Quit) return;
    expireWith(problem(Code::Interrupted, "the window was closed again while stopping: stopped at once"), 130);
}

std::optional<Diagnostic> Watchdog::expired() const {
    std::lock_guard lock(mutex_);
    return expired_;
}

void Watchdog::expireWith(Diagnostic diagnostic, int exitCode) {
    {
        std::lock_guard lock(mutex_);
        if (expired_) return;
        expired_ = diagnostic;
    }
    activity_.cancel();
    if (desc_.expire) desc_.expire(diagnostic, exitCode);
    requestStop(StopReason::Request);
}

void Watchdog::acknowledgeSignal(int signal) {
    if (++signals_ > 1) {
        const StopState first = stop();
        expireWith(problem(Code::Interrupted, std::string(stopSignalName(signal)) + " again: stopped at once"),
                   128 + (first.signal ? first.signal : signal));
        return;
    }
    requestStop(StopReason::Signal, signal);
    if (desc_.acknowledge) {
        Diagnostic d = problem(Code::Interrupted, std::string(stopSignalName(signal)) +
                                                      ": stopping before the next frame (again to stop at once)");
        d.severity = Severity::Notice;
        desc_.acknowledge(d);
    }
}

void Watchdog::loop() {
    using Clock = std::chrono::steady_clock;
    const int signalFd = desc_.watchSignals ? stopSignalFd() : -1;
    pollfd fds[2] = {{done_.pollFd(), POLLIN, 0}, {signalFd, POLLIN, 0}};
    while (true) {
        ::poll(fds, signalFd >= 0 ? 2 : 1, kTickMilliseconds);
        if (fds[0].revents) return;
        const Clock::time_point tick = Clock::now();
        pauses_.tick(tick);
        if (signalFd >= 0 && (fds[1].revents & POLLIN)) {
            unsigned char received[16];
            const ssize_t n = ::read(signalFd, received, sizeof received);
            for (ssize_t i = 0; i < n; ++i) acknowledgeSignal(received[i]);
        }
        // A frame an encoder finishes after a stop is not a stuck render: the grace period starts
        // again when it is done (the frame limit still bounds it, and a second signal still ends
        // the run at once).
        const bool finishingFrames = activity_.snapshot().phase == RunActivity::Phase::Abandoning;
        {
            std::unique_lock lock(mutex_);
            if (finishingFrames && graceArmed_) stopAt_ = tick;
            const StopState s = stop_;
            const double since = pauses_.runningSeconds(stopAt_, tick);
            const bool armed = graceArmed_ && !expired_;
            lock.unlock();
            if (armed && since > desc_.graceSeconds) {
                const std::string what = s.reason == StopReason::Quit ? "the window was closed, but the frame being drawn"
                                                                      : "the render thread";
                expireWith(problem(Code::Interrupted, what + " did not stop within " + seconds(desc_.graceSeconds) +
                                                          " s (GL cannot be interrupted): stopped"),
                           s.reason == StopReason::Signal ? 128 + s.signal : 130);
            }
        }

        RunActivity::Snapshot now = activity_.snapshot();
        now.seconds = pauses_.runningSeconds(now.since, Clock::now());
        const double frameLimit = desc_.frameLimit, compileLimit = desc_.compileLimit;
        const bool drawing = now.phase == RunActivity::Phase::Drawing || now.phase == RunActivity::Phase::DrawCall;
        if (frameLimit > 0 && drawing && now.samples > 1 && now.seconds > frameLimit)
            // One of a frame's several draws (supersampling, motion blur): the limit is per draw.
            expireWith(problem(Code::WatchdogFrame,
                               "frame " + std::to_string(now.frame) + " has been drawing sample " +
                                   std::to_string(now.sample + 1) + " of " + std::to_string(now.samples) +
                                   " of this pass (--supersample, --motion-blur) for " + seconds(now.seconds) +
                                   " s, longer than --frame-timeout " + seconds(frameLimit) +
                                   ", which bounds each sample's draw: the run is ended (a shader that loops too "
                                   "long? " +
                                   (now.frame <= 0 && now.sample == 0
                                        ? std::string("The first sample's draw may also be the driver compiling the "
                                                      "pass: with Mesa's llvmpipe, GALLIVM_PERF=nopt in the "
                                                      "environment makes such compiles fast. ")
                                        : std::string()) +
                                   "--frame-timeout 0 turns the limit off)",
                               now.pass),
                       kExitWatchdog);
        else if (frameLimit > 0 && now.phase == RunActivity::Phase::Drawing && now.seconds > frameLimit)
            expireWith(problem(Code::WatchdogFrame,
                               "frame " + std::to_string(now.frame) + " has been drawing this pass for " +
                                   seconds(now.seconds) + " s, longer than --frame-timeout " + seconds(frameLimit) +
                                   ": the run is ended (a shader that loops too long? " +
                                   (now.frame <= 0 ? std::string("On frame 0 it may also be the driver compiling the pass "
                                                                 "inside its first draw: with Mesa's llvmpipe, "
                                                                 "GALLIVM_PERF=nopt in the environment makes such compiles "
                                                                 "fast. ")
                                                   : std::string()) +
                                   "--frame-timeout 0 turns the limit off)",
                               now.pass),
                       kExitWatchdog);
        else if (frameLimit > 0 && now.phase == RunActivity::Phase::DrawCall && now.seconds > frameLimit)
            expireWith(problem(Code::WatchdogFrame,
                               "frame " + std::to_string(now.frame) + " has been drawing this pass for " +
                                   seconds(now.seconds) + " s, longer than --frame-timeout " + seconds(frameLimit) +
                                   ": the run is ended. Its draw call has not returned: the driver compiles a pass's "
                                   "machine code inside its first draw (llvmpipe does), so " +
                                   (now.frame <= 0 ? std::string("this pass's compile is what stalls (many loops bounded by "
                                                                 "iTime or iFrame make LLVM's loop analysis slow; with Mesa's "
                                                                 "llvmpipe, GALLIVM_PERF=nopt in the environment compiles them "
                                                                 "in a fraction of the time)")
                                                   : std::string("a recompile of this pass or its drawing stalls")) +
                                   "; --frame-timeout 0 turns the limit off",
                               now.pass),
                       kExitWatchdog);
        else if (frameLimit > 0 && now.phase == RunActivity::Phase::WaitingForInput && now.seconds > frameLimit)
            expireWith(problem(Code::WatchdogInput,
                               "frame " + std::to_string(now.frame) + " has waited " + seconds(now.seconds) +
                                   " s for a video decoder, longer than --frame-timeout " + seconds(frameLimit) +
                                   ": the run is ended (a stalled ffmpeg or camera?)",
                               now.pass),
                       kExitWatchdog);
        else if (frameLimit > 0 &&
                 (now.phase == RunActivity::Phase::WaitingForOutput || now.phase == RunActivity::Phase::Abandoning) &&
                 now.seconds > frameLimit)
            expireWith(problem(Code::WatchdogOutput,
                               "the encoders have taken no frame for " + seconds(now.seconds) +
                                   " s, longer than --frame-timeout " + seconds(frameLimit) +
                                   ": the run is ended (a stalled ffmpeg, or a reader of --out - that stopped reading?)"),
                       kExitWatchdog);
        else if (compileLimit > 0 && now.phase == RunActivity::Phase::Compiling && now.seconds > compileLimit)
            expireWith(problem(Code::WatchdogCompile,
                               "compiling has taken " + seconds(now.seconds) + " s, longer than --compile-timeout " +
                                   seconds(compileLimit) + ": the run is ended (--compile-timeout 0 turns the limit off)",
                               now.pass),
                       kExitWatchdog);
    }
}

}  // namespace toyhost
