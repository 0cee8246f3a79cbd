#include "Console.h"

#include "SessionFlags.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

#include "core/InFlight.h"
#include "session/StopSignals.h"
#include "timing/ProgressLine.h"

namespace toyhost::cli {

void printDiagnostic(const Diagnostic& diagnostic) {
    std::cerr << formatDiagnosticWithExcerpt(diagnostic, "toyhost: ") << "\n";
}

namespace {
int firstStdoutErrno = 0;
}

bool flushStdout() {
    errno = 0;
    const bool ok = std::fflush(stdout) == 0 && !std::ferror(stdout) && std::cout.good();
    if (!ok && firstStdoutErrno == 0) firstStdoutErrno = errno;
    return ok;
}

int stdoutWriteErrno() { return firstStdoutErrno; }

void printError(const Error& error) { std::cerr << formatDiagnostics(error.diagnostics, "toyhost: ") << "\n"; }

int fail(const Error& error) {
    printError(withFlagNames(error));
    // Whatever ended a run that a signal asked to stop, the shell's convention says so.
    if (stopSignal()) return 128 + stopSignal();
    switch (error.category()) {
        case Category::Usage: return kExitUsage;
        case Category::Watchdog: return kExitWatchdog;
        case Category::Interrupted: return 128 + (stopSignal() ? stopSignal() : SIGINT);
        default: return kExitFailure;
    }
}

int usage(const std::string& message) {
    std::cerr << "toyhost: error: " << message << " [usage]\n";
    return kExitUsage;
}

ConsoleObserver::ConsoleObserver(bool quiet) : quiet_(quiet), show_(!quiet && isatty(STDERR_FILENO)) {}

void ConsoleObserver::clearProgress() {
    if (shown_) std::cerr << "\r\033[K";
    shown_ = false;
}

void ConsoleObserver::summary(const SessionReport& report) {
    std::lock_guard lock(mutex_);
    clearProgress();
    for (const std::string& line : summaryLines(report)) std::cerr << "toyhost: " << line << "\n";
}

void ConsoleObserver::roundFinished(const Result<SessionReport>& round) {
    // The first round's summary says where and how it ran; later rounds (the reload's notice
    // before them) take one line.
    const bool first = rounds_++ == 0;
    if (round && first) summary(*round);
    std::lock_guard lock(mutex_);
    clearProgress();
    if (!round) printError(round.error());
    if (round && !first) std::cerr << "toyhost: " << watchRoundLine(*round) << "; watching the shadertoy's files (Ctrl-C ends)\n";
    else std::cerr << "toyhost: watching the shadertoy's files; Ctrl-C ends\n";
}

void ConsoleObserver::notice(const Diagnostic& notice) {
    if (quiet_ && notice.severity == Severity::Notice) return;
    std::lock_guard lock(mutex_);
    clearProgress();
    printDiagnostic(notice);
}

void ConsoleObserver::problems(const std::vector<Diagnostic>& list) {
    std::lock_guard lock(mutex_);
    clearProgress();
    std::cerr << formatDiagnostics(list, "toyhost: ") << "\n";
}

void ConsoleObserver::progress(const RunProgress& p) {
    if (!show_) return;
    std::lock_guard lock(mutex_);
    // At most five updates a second: a terminal write per frame would cost more than a fast
    // shader's frame.
    const auto now = std::chrono::steady_clock::now();
    const bool last = p.frames > 0 && p.framesDone == p.frames;
    if (!last && shown_ && now - lastShown_ < std::chrono::milliseconds(200)) return;
    lastShown_ = now;
    if (last) {
        clearProgress();
        std::cerr << std::flush;
        return;
    }
    shown_ = true;
    std::cerr << "\r\033[K" << formatProgressLine(p) << std::flush;
}

namespace {
// Written with write(2): the expiry runs on the watchdog's thread while the render thread may hold
// the stream locks.
void say(const std::string& line) {
    const std::string text = (isatty(STDERR_FILENO) ? "\r\033[K" : "") + line + "\n";
    (void)!::write(STDERR_FILENO, text.data(), text.size());
}
}  // namespace

void endAfterWatchdog(const Diagnostic& d, int exitCode) {
    // Nothing half-written may stay: unfinished files go and encoders are stopped before the
    // process ends.
    const inflight::CleanupReport cleaned = inflight::emergencyCleanup();
    std::string line = "toyhost: " + formatDiagnostic(d);
    if (cleaned.files || cleaned.children)
        line += " (removed " + std::to_string(cleaned.files) + " unfinished file" + (cleaned.files == 1 ? "" : "s") +
                ", stopped " + std::to_string(cleaned.children) + " child process" +
                (cleaned.children == 1 ? "" : "es") + ")";
    say(line);
    ::_exit(exitCode);
}

int runSession(const SessionOptions& options, bool quiet, const SessionRunner& driver) {
    WatchdogHooks hooks;
    hooks.watchSignals = true;
    hooks.acknowledge = [](const Diagnostic& d) { say("toyhost: " + formatDiagnostic(d)); };
    hooks.expire = [](const Diagnostic& d, int exitCode) { endAfterWatchdog(d, exitCode); };
    const std::unique_ptr<Watchdog> watchdog = makeWatchdog(options, std::move(hooks));
    ConsoleObserver observer(quiet);
    Result<SessionReport> report = driver(options, observer, watchdog.get());
    if (!report) return fail(report.error());
    if (!options.watch) observer.summary(*report);
    return kExitOk;
}

}  // namespace toyhost::cli
