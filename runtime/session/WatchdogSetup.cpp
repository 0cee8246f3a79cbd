#include "session/WatchdogSetup.h"

namespace toyhost {

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

}  // namespace toyhost
