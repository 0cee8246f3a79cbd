// PauseLedger: a gap between ticks longer than the period plus the minimum pause is time the
// process did not run, and a phase's running time leaves it out (the watchdog's suspension rule).
#include <gtest/gtest.h>

#include "core/PauseLedger.h"

using namespace toyhost;
using Clock = PauseLedger::Clock;

namespace {
Clock::time_point at(double seconds) {
    return Clock::time_point{} + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}
void tickEvery(PauseLedger& ledger, double from, double to, double step) {
    for (double t = from; t <= to + 1e-9; t += step) ledger.tick(at(t));
}
}  // namespace

TEST(PauseLedger, RegularTicksAndSchedulingNoiseCountAsRunning) {
    PauseLedger ledger(0.05, 1.0);
    tickEvery(ledger, 100, 110, 0.05);
    ledger.tick(at(110.5));  // a 0.5 s wait for a core on a loaded machine: it ran
    tickEvery(ledger, 110.55, 112, 0.05);
    EXPECT_EQ(ledger.pausesKept(), 0u);
    EXPECT_NEAR(ledger.runningSeconds(at(101), at(112)), 11.0, 1e-6);
}

TEST(PauseLedger, ASuspensionIsLeftOutOfPhasesThatSpanIt) {
    PauseLedger ledger(0.05, 1.0);
    tickEvery(ledger, 100, 101, 0.05);
    ledger.tick(at(131));  // SIGSTOP at ~101, SIGCONT at 131
    tickEvery(ledger, 131.05, 132, 0.05);
    ASSERT_EQ(ledger.pausesKept(), 1u);
    // A frame that began at 100.5 has run 0.5 s before the stop, 0.05 s of the gap's tick, and 1 s after.
    EXPECT_NEAR(ledger.runningSeconds(at(100.5), at(132)), 1.55, 1e-6);
    // A phase that began after the suspension is not affected.
    EXPECT_NEAR(ledger.runningSeconds(at(131.5), at(132)), 0.5, 1e-6);
    // One that ended before it is not either.
    EXPECT_NEAR(ledger.runningSeconds(at(100), at(101)), 1.0, 1e-6);
}

TEST(PauseLedger, APhaseThatBeganInsideAGapCountsOnlyWhatFollowsIt) {
    PauseLedger ledger(0.05, 1.0);
    ledger.tick(at(10));
    ledger.tick(at(20));  // paused from 10.05 to 20
    EXPECT_NEAR(ledger.runningSeconds(at(15), at(21)), 1.0, 1e-6);
    EXPECT_EQ(ledger.runningSeconds(at(21), at(20)), 0.0);
}

TEST(PauseLedger, SeveralPausesAddUpAndTheLedgerStaysBounded) {
    PauseLedger ledger(0.05, 1.0);
    double t = 0;
    for (int i = 0; i < 1000; ++i) {
        ledger.tick(at(t));
        t += 0.05;
        ledger.tick(at(t));
        t += 2.0;  // a 1.95 s pause after each tick pair
    }
    ledger.tick(at(t));  // the tick that notices the last pause
    EXPECT_LE(ledger.pausesKept(), 256u);
    // Over the last three cycles: the 0.05 between the pair's ticks plus the tick period before each pause.
    const double since = t - 3 * 2.05;
    EXPECT_NEAR(ledger.runningSeconds(at(since), at(t)), 3 * 0.1, 1e-6);
}
