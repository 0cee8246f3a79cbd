// Console: how the toyhost CLI talks to the user. Every diagnostic is printed the same way
// ("toyhost: " + formatDiagnostic), notices and progress go to stderr (stdout may carry raw
// frames), and the exit code follows from the error (docs/cli.md lists them). Ctrl-C and SIGTERM
// ask a running job to stop.
#pragma once

#include <chrono>
#include <csignal>
#include <functional>
#include <string>

#include "core/Result.h"
#include "session/SessionObserver.h"

namespace toyhost::cli {

// Exit codes (docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // the run failed: bad manifest, shader error, GL, I/O
inline constexpr int kExitUsage = 2;    // bad command line

void printDiagnostic(const Diagnostic& diagnostic);
void printError(const Error& error);
// Prints `error` and returns its exit code: 2 for usage errors, 128 + signal when a signal
// interrupted the run, else 1.
int fail(const Error& error);
// A usage error with one message; returns 2.
int usage(const std::string& message);

// SIGINT/SIGTERM set a flag that stopRequested() reads, and wake the StopWatcher (readable on
// stopSignalFd()), which acknowledges them and ends the process if the run cannot stop in time.
void installStopSignals();
int stopSignal();
int stopSignalFd();

class ConsoleObserver final : public SessionObserver {
public:
    // `summary` prints a finished round of a --watch run. `quiet`: no progress line and no
    // notices (warnings and errors still print).
    explicit ConsoleObserver(bool quiet, std::function<void(const SessionReport&)> summary = {},
                             RunActivity* activity = nullptr);
    RunActivity* activity() override { return activity_; }
    void notice(const Diagnostic& notice) override;
    bool stopRequested() const override { return stopSignal() != 0; }
    void progress(const RunProgress& p) override;
    void roundFinished(const Result<SessionReport>& round) override;

private:
    std::function<void(const SessionReport&)> summary_;
    RunActivity* activity_;
    bool quiet_;
    bool show_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point lastShown_;
};

}  // namespace toyhost::cli
