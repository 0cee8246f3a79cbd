#include "Console.h"

#include <iostream>
#include <unistd.h>

#include "timing/ProgressLine.h"

namespace toyhost::cli {

namespace {
// Set by SIGINT/SIGTERM: the run stops before its next frame and cleans up (a second signal
// kills the process at once).
volatile std::sig_atomic_t stopSignalNumber = 0;
extern "C" void onStopSignal(int signal) {
    stopSignalNumber = signal;
    std::signal(signal, SIG_DFL);
}
}  // namespace

void printDiagnostic(const Diagnostic& diagnostic) { std::cerr << "toyhost: " << formatDiagnostic(diagnostic) << "\n"; }

void printError(const Error& error) { std::cerr << formatDiagnostics(error.diagnostics, "toyhost: ") << "\n"; }

int fail(const Error& error) {
    printError(error);
    if (stopSignalNumber) return 128 + stopSignalNumber;  // the shell's convention for a signal
    if (error.first().code.rfind("usage", 0) == 0) return kExitUsage;
    return kExitFailure;
}

int usage(const std::string& message) {
    std::cerr << "toyhost: error: " << message << " [usage]\n";
    return kExitUsage;
}

void installStopSignals() {
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);
}

int stopSignal() { return stopSignalNumber; }

ConsoleObserver::ConsoleObserver(bool quiet, std::function<void(const RunReport&)> summary)
    : summary_(std::move(summary)), quiet_(quiet), show_(!quiet && isatty(STDERR_FILENO)) {}

void ConsoleObserver::roundFinished(const Result<RunReport>& round) {
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
