// WatchdogSetup: the one place a session's watchdog is made from its settings (the limits, after
// defaults) and from what its program wants on top (the CLI: signals, a message, an exit; the
// library: the embedder's expiry handler). The watchdog is then attached to the session's GL
// context (GlContext::gpuActivity()), where everything that renders publishes. No GL needed.
#pragma once

#include <functional>
#include <memory>

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

}  // namespace toyhost
