#include "core/PauseLedger.h"

#include <algorithm>

namespace toyhost {

void PauseLedger::tick(Clock::time_point now) {
    if (ticked_) {
        const double gap = std::chrono::duration<double>(now - lastTick_).count();
        if (gap > tickPeriod_ + minPause_) {
            // The expected tick period is the running part of the gap; the rest did not run.
            const auto ran = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(tickPeriod_));
            pauses_.push_back({lastTick_ + ran, now});
            if (pauses_.size() > kKept) pauses_.pop_front();
        }
    }
    ticked_ = true;
    lastTick_ = now;
}

double PauseLedger::runningSeconds(Clock::time_point since, Clock::time_point now) const {
    if (now <= since) return 0;
    Clock::duration paused{0};
    for (const Pause& p : pauses_) {
        const Clock::time_point from = std::max(p.from, since), to = std::min(p.to, now);
        if (to > from) paused += to - from;
    }
    return std::max(0.0, std::chrono::duration<double>(now - since - paused).count());
}

}  // namespace toyhost
