// PauseLedger: the stretches of wall time in which the process did not run (SIGSTOP, Ctrl-Z, a
// scheduler's suspend, a laptop's sleep), noticed by a thread that ticks often as a gap between two
// ticks, so that a limit on how long something took counts only the time the process ran. No GL.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>

namespace toyhost {

class PauseLedger {
public:
    using Clock = std::chrono::steady_clock;

    // `tickPeriod`: how often tick() is called; a gap longer than tickPeriod + `minPause` between
    // two ticks is recorded as a pause (shorter gaps are scheduling noise and stay counted).
    PauseLedger(double tickPeriod, double minPause) : tickPeriod_(tickPeriod), minPause_(minPause) {}

    // Called by the ticking thread at `now` (steady, non-decreasing).
    void tick(Clock::time_point now);

    // Seconds from `since` to `now` that the process ran: the wall time less the pauses inside it.
    double runningSeconds(Clock::time_point since, Clock::time_point now) const;

    std::size_t pausesKept() const { return pauses_.size(); }

private:
    struct Pause {
        Clock::time_point from, to;
    };
    double tickPeriod_, minPause_;
    bool ticked_ = false;
    Clock::time_point lastTick_;
    std::deque<Pause> pauses_;  // oldest first; only the last kKept matter to any phase still running
    static constexpr std::size_t kKept = 256;
};

}  // namespace toyhost
