// Console: how the toyhost CLI talks to the user. Every diagnostic is printed the same way
// ("toyhost: " + formatDiagnostic), notices, progress and summaries go to stderr (stdout may carry
// raw frames or audio), and the exit code follows the error's category (docs/cli.md lists them).
// runSession is the one way every command that renders runs: a SessionCore behind a watchdog whose
// expiry ends the process (after removing unfinished files), printing what the session reports.
#pragma once

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

#include "core/Result.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"
#include "session/WatchdogSetup.h"

namespace toyhost::cli {

// Exit codes (docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the run failed: bad manifest, shader error, GL, I/O
inline constexpr int kExitUsage = 2;    // bad command line

// Flushes stdout (a report, a list): false when writing failed; the first failure's errno is kept
// for the check every command ends with (main.cpp), which says what was lost.
bool flushStdout();
int stdoutWriteErrno();

void printDiagnostic(const Diagnostic& diagnostic);
void printError(const Error& error);
// Prints `error` and returns its exit code: 2 for usage errors, 124 when the watchdog ended the
// run, 128 + signal when a signal interrupted it, else 1.
int fail(const Error& error);
// A usage error with one message; returns 2.
int usage(const std::string& message);

class ConsoleObserver final : public SessionObserver {
public:
    // `quiet`: no progress line and no notices (warnings and errors still print).
    explicit ConsoleObserver(bool quiet);
    void notice(const Diagnostic& notice) override;
    void problems(const std::vector<Diagnostic>& list) override;
    void progress(const RunProgress& p) override;
    void roundFinished(const Result<SessionReport>& round) override;
    // Prints the summary of a finished run.
    void summary(const SessionReport& report);

private:
    void clearProgress();
    std::mutex mutex_;  // notices may come from the watchdog's thread
    bool quiet_;
    bool show_;
    bool shown_ = false;
    int rounds_ = 0;  // --watch rounds finished
    std::chrono::steady_clock::time_point lastShown_;
};

// Ends the process now because the watchdog expired (`d` says why), from the watchdog's thread
// while the GL thread may be stuck: unfinished files are removed and child processes stopped, the
// diagnostic is printed, and the process exits with `exitCode` (124 for a limit).
[[noreturn]] void endAfterWatchdog(const Diagnostic& d, int exitCode);

// The way a command runs a session (`driver` is runHeadless or runWindow): with the watchdog the
// options ask for and SIGINT/SIGTERM handling, printing notices, progress and the summary.
// Returns the exit code.
using SessionRunner = std::function<Result<SessionReport>(const SessionOptions&, SessionObserver&, Watchdog*)>;
int runSession(const SessionOptions& options, bool quiet, const SessionRunner& driver);

}  // namespace toyhost::cli
