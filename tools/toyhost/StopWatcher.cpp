#include "StopWatcher.h"

#include <chrono>
#include <cstdio>
#include <poll.h>
#include <string>
#include <unistd.h>

#include "Console.h"
#include "core/Diagnostic.h"
#include "core/InFlight.h"

namespace toyhost::cli {

namespace {
const char* signalName(int signal) { return signal == SIGTERM ? "SIGTERM" : signal == SIGINT ? "SIGINT" : "a signal"; }

void say(const std::string& line) {
    // Past a progress line, if one is shown.
    const std::string text = (isatty(STDERR_FILENO) ? "\r\033[K" : "") + line + "\n";
    (void)!::write(STDERR_FILENO, text.data(), text.size());
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, s == static_cast<long long>(s) ? "%.0f" : "%.1f", s);
    return text;
}
}  // namespace

StopWatcher::StopWatcher(double frameLimit, double compileLimit, double graceSeconds)
    : frameLimit_(frameLimit), compileLimit_(compileLimit), grace_(graceSeconds), thread_([this] { loop(); }) {}

StopWatcher::~StopWatcher() {
    done_.cancel();
    thread_.join();
}

void StopWatcher::endNow(int exitCode, const char* why) {
    const inflight::CleanupReport cleaned = inflight::emergencyCleanup();
    std::string line = std::string("toyhost: ") + why;
    if (exitCode != kExitTimeout) line = "toyhost: error: interrupted: " + std::string(why);
    if (cleaned.files || cleaned.children)
        line += " (removed " + std::to_string(cleaned.files) + " unfinished file" + (cleaned.files == 1 ? "" : "s") +
                ", stopped " + std::to_string(cleaned.children) + " child process" + (cleaned.children == 1 ? "" : "es") +
                ")";
    if (exitCode != kExitTimeout) line += " [interrupted]";
    say(line);
    ::_exit(exitCode);
}

void StopWatcher::loop() {
    using Clock = std::chrono::steady_clock;
    int signals = 0, first = 0;
    Clock::time_point firstAt;
    pollfd fds[2] = {{stopSignalFd(), POLLIN, 0}, {done_.pollFd(), POLLIN, 0}};
    while (true) {
        ::poll(fds, 2, 100);
        if (fds[1].revents) return;
        if (fds[0].revents & POLLIN) {
            unsigned char received[16];
            const ssize_t n = ::read(fds[0].fd, received, sizeof received);
            for (ssize_t i = 0; i < n; ++i) {
                if (++signals == 1) {
                    first = received[i];
                    firstAt = Clock::now();
                    say(std::string("toyhost: ") + signalName(first) +
                        ": stopping before the next frame (again to stop at once)");
                } else {
                    endNow(128 + first, (std::string(signalName(received[i])) + " again: stopped at once").c_str());
                }
            }
        }
        if (signals && std::chrono::duration<double>(Clock::now() - firstAt).count() > grace_)
            endNow(128 + first, ("the render thread did not stop within " + seconds(grace_) +
                                 " s (GL cannot be interrupted): stopped")
                                    .c_str());

        const RunActivity::Snapshot now = activity_.snapshot();
        Diagnostic d;
        bool expired = true;
        if (frameLimit_ > 0 && now.phase == RunActivity::Phase::Drawing && now.seconds > frameLimit_) {
            d.code = Code::WatchdogFrame;
            d.pass = now.pass;
            d.message = "frame " + std::to_string(now.frame) + " has been drawing this pass for " +
                        seconds(now.seconds) + " s, longer than --frame-timeout " + seconds(frameLimit_) +
                        ": the run is ended (a shader that loops too long? --frame-timeout 0 turns the limit off)";
        } else if (frameLimit_ > 0 && now.phase == RunActivity::Phase::WaitingForOutput && now.seconds > frameLimit_) {
            d.code = Code::WatchdogOutput;
            d.message = "the encoders have taken no frame for " + seconds(now.seconds) +
                        " s, longer than --frame-timeout " + seconds(frameLimit_) +
                        ": the run is ended (a stalled ffmpeg, or a reader of --out - that stopped reading?)";
        } else if (compileLimit_ > 0 && now.phase == RunActivity::Phase::Compiling && now.seconds > compileLimit_) {
            d.code = Code::WatchdogCompile;
            d.pass = now.pass;
            d.message = "compiling has taken " + seconds(now.seconds) + " s, longer than --compile-timeout " +
                        seconds(compileLimit_) + ": the run is ended (--compile-timeout 0 turns the limit off)";
        } else {
            expired = false;
        }
        if (expired) endNow(kExitTimeout, formatDiagnostic(d).c_str());
    }
}

}  // namespace toyhost::cli
