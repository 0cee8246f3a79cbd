// WatchdogSetup: the one place a session's watchdog is made from its settings (the limits, after
// defaults) and from what its program wants on top (the CLI: signals, a message, an exit; the
// library: the embedder's expiry handler, process-wide, kept here). The watchdog is then attached
// to the session's GL context (GlContext::gpuActivity()), where everything that renders publishes.
// No GL needed.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/Diagnostic.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"

namespace toyhost {

// What the program adds to the limits (see WatchdogDesc).
struct WatchdogHooks {
    bool watchSignals = false;
    std::function<void(const Diagnostic&)> acknowledge;
    std::function<void(const Diagnostic&, int exitCode)> expire;
};

// The limits of `options` (defaults applied: core/Defaults.h).
WatchdogDesc watchdogDesc(const SessionOptions& options, WatchdogHooks hooks = {});
// A watchdog for `options`, or null when it would watch nothing (no limit and no signals): a
// session without one costs no thread.
std::unique_ptr<Watchdog> makeWatchdog(const SessionOptions& options, WatchdogHooks hooks = {});

// The library's expiry handler (toyhost::setWatchdogExpiryHandler), one for the process: what
// happens when a library session's limit passes while its thread is still inside GL. Empty (the
// default): nothing more, the call returns the error once GL does. Any thread.
void setLibraryExpiryHandler(std::function<void(const Diagnostic&)> handler);
// Hooks for a library session of the shadertoy at `file`: an expiry calls the handler set when it
// happens (if any) with the diagnostic, its file set to `file` when it names none.
WatchdogHooks libraryExpiryHooks(std::string file);

}  // namespace toyhost
