#include "Console.h"

#include <cerrno>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

#include "timing/ProgressLine.h"

namespace toyhost::cli {

namespace {
// Set by SIGINT/SIGTERM: the run stops before its next frame. Every signal is also written to a
// pipe that the StopWatcher thread reads: it acknowledges the signal, and ends the process (after
// removing unfinished files) at a second signal or when the run does not stop in time.
volatile std::sig_atomic_t stopSignalNumber = 0;
int signalPipe[2] = {-1, -1};
extern "C" void onStopSignal(int signal) {
    const int savedErrno = errno;
    if (!stopSignalNumber) stopSignalNumber = signal;
    const unsigned char byte = static_cast<unsigned char>(signal);
    (void)!::write(signalPipe[1], &byte, 1);
    errno = savedErrno;
}
}  // namespace

void printDiagnostic(const Diagnostic& diagnostic) { std::cerr << "toyhost: " << formatDiagnostic(diagnostic) << "\n"; }

void printError(const Error& error) { std::cerr << formatDiagnostics(error.diagnostics, "toyhost: ") << "\n"; }

int fail(const Error& error) {
    printError(error);
    if (stopSignalNumber) return 128 + stopSignalNumber;  // the shell's convention for a signal
    if (error.category() == Category::Usage) return kExitUsage;
    return kExitFailure;
}

int usage(const std::string& message) {
    std::cerr << "toyhost: error: " << message << " [usage]\n";
    return kExitUsage;
}

void installStopSignals() {
    if (signalPipe[0] < 0 && ::pipe2(signalPipe, O_CLOEXEC | O_NONBLOCK) != 0) signalPipe[0] = signalPipe[1] = -1;
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
}

int stopSignalFd() { return signalPipe[0]; }

int stopSignal() { return stopSignalNumber; }

ConsoleObserver::ConsoleObserver(bool quiet, std::function<void(const SessionReport&)> summary, RunActivity* activity)
    : summary_(std::move(summary)), activity_(activity), quiet_(quiet), show_(!quiet && isatty(STDERR_FILENO)) {}

void ConsoleObserver::roundFinished(const Result<SessionReport>& round) {
    if (shown_) std::cerr << "\r\033[K";
    shown_ = false;
    if (round) {
        if (summary_) summary_(*round);
    } else {
        printError(round.error());
    }
    std::fprintf(stderr, "toyhost: watching the shadertoy's files; Ctrl-C ends\n");
}

void ConsoleObserver::notice(const Diagnostic& notice) {
    if (quiet_ && notice.severity == Severity::Notice) return;
    if (shown_) std::cerr << "\r\033[K";
    shown_ = false;
    printDiagnostic(notice);
}

void ConsoleObserver::progress(const RunProgress& p) {
    if (!show_) return;
    // At most five updates a second: a terminal write per frame would cost more than a fast
    // shader's frame.
    const auto now = std::chrono::steady_clock::now();
    const bool last = p.frames > 0 && p.framesDone == p.frames;
    if (!last && shown_ && now - lastShown_ < std::chrono::milliseconds(200)) return;
    lastShown_ = now;
    shown_ = !last;
    if (last) std::cerr << "\r\033[K" << std::flush;
    else std::cerr << "\r\033[K" << formatProgressLine(p) << std::flush;
}

}  // namespace toyhost::cli
