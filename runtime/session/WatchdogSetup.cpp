#include "session/WatchdogSetup.h"

#include <mutex>

namespace toyhost {

namespace {
// setLibraryExpiryHandler's handler, read by every library session's watchdog when a limit passes.
std::mutex expiryMutex;
std::function<void(const Diagnostic&)>& expiryHandler() {
    static std::function<void(const Diagnostic&)> handler;
    return handler;
}
}  // namespace

WatchdogDesc watchdogDesc(const SessionOptions& options, WatchdogHooks hooks) {
    const SessionOptions resolved = withDefaults(options);
    WatchdogDesc desc;
    desc.frameLimit = *resolved.settings.frameTimeout;
    desc.compileLimit = *resolved.settings.compileTimeout;
    desc.watchSignals = hooks.watchSignals;
    desc.acknowledge = std::move(hooks.acknowledge);
    desc.expire = std::move(hooks.expire);
    return desc;
}

std::unique_ptr<Watchdog> makeWatchdog(const SessionOptions& options, WatchdogHooks hooks) {
    WatchdogDesc desc = watchdogDesc(options, std::move(hooks));
    if (desc.frameLimit <= 0 && desc.compileLimit <= 0 && !desc.watchSignals) return nullptr;
    return std::make_unique<Watchdog>(std::move(desc));
}

void setLibraryExpiryHandler(std::function<void(const Diagnostic&)> handler) {
    std::lock_guard<std::mutex> lock(expiryMutex);
    expiryHandler() = std::move(handler);
}

WatchdogHooks libraryExpiryHooks(std::string file) {
    WatchdogHooks hooks;
    hooks.expire = [file = std::move(file)](const Diagnostic& expired, int) {
        std::function<void(const Diagnostic&)> handler;
        {
            std::lock_guard<std::mutex> lock(expiryMutex);
            handler = expiryHandler();
        }
        if (!handler) return;
        Diagnostic named = expired;
        if (named.file.empty()) named.file = file;
        handler(named);
    };
    return hooks;
}

}  // namespace toyhost
