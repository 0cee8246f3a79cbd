// InFlight: the temporary files and child processes a run has under way, so that an emergency
// exit (a second Ctrl-C, a signal the render thread cannot answer in time, the watchdog) removes
// them before the process ends: no half-written file and no orphaned encoder is left behind.
// Thread-safe; the writers register what they create, the CLI's watcher thread cleans up.
// No GL needed.
#pragma once

#include <filesystem>
#include <sys/types.h>

namespace toyhost::inflight {

// Registers a temporary file about to be created (call before creating it). False once an
// emergency cleanup has begun: the caller must not create the file.
bool addFile(const std::filesystem::path& path);
// The file is no longer temporary (renamed into place, or removed).
void removeFile(const std::filesystem::path& path);

// A child process that is running (registered right after it starts, removed once reaped).
void addChild(pid_t pid);
void removeChild(pid_t pid);

struct CleanupReport {
    int files = 0;     // temporary files removed
    int children = 0;  // child processes killed
};

// Kills every registered child (SIGKILL, then waits up to a second for each to die, so none can
// create a file afterwards) and removes every registered temporary file, twice with a short
// pause between, for writers that registered a file just before the cleanup began. Every
// registration fails afterwards. Call it right before ending the process.
CleanupReport emergencyCleanup();

}  // namespace toyhost::inflight
