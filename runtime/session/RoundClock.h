// RoundClock: a session's round statistics, apart from its loop: when the command and the round
// started, the frames rendered this round, the time spent in the player's frame calls and GPU
// waits, the end of the first frame and the time the run stood paused (a window's pause, which
// the report's frame rate leaves out); the report's times and the progress line are made from
// them. No GL needed.
#pragma once

#include <algorithm>
#include <chrono>

#include "session/SessionObserver.h"

namespace toyhost {

class RoundClock {
public:
    using Clock = std::chrono::steady_clock;

    static double secondsBetween(Clock::time_point from, Clock::time_point to) {
        return std::chrono::duration<double>(to - from).count();
    }

    // The command started at `at` (start-up counts from there), or a next --watch round now.
    void startCommand(Clock::time_point at = Clock::now()) { startedAt_ = at; }
    double secondsSinceCommand() const { return secondsBetween(startedAt_, Clock::now()); }
    // A round begins: its counts start over; the start-up time so far.
    double beginRound() {
        frames_ = 0;
        renderSeconds_ = 0;
        pausedSeconds_ = 0;
        roundStartedAt_ = Clock::now();
        return secondsBetween(startedAt_, roundStartedAt_);
    }
    // Before a rendered frame: the first one restarts the round's clock and gives the start-up time.
    std::optional<double> frameStarting() {
        if (frames_ > 0) return std::nullopt;
        roundStartedAt_ = Clock::now();
        return secondsBetween(startedAt_, roundStartedAt_);
    }
    // `work` (a frame call or a GPU wait) counted as render time.
    template <class Work>
    void timed(Work work) {
        const Clock::time_point started = Clock::now();
        work();
        renderSeconds_ += secondsBetween(started, Clock::now());
    }
    void frameDone() {
        if (frames_ == 0) firstFrameEndedAt_ = Clock::now();
        ++frames_;
    }
    // The loop had no frame to render and waited in `wait`; while `paused` (a window's pause, not
    // a paced wait for the next frame) that time is left out of the frames' time once a frame
    // was rendered.
    template <class Wait>
    void idle(bool paused, Wait wait) {
        const Clock::time_point started = Clock::now();
        wait();
        if (paused) idled(started, Clock::now());
    }
    void idled(Clock::time_point from, Clock::time_point to) {
        if (frames_ > 0) pausedSeconds_ += secondsBetween(from, to);
    }

    int frames() const { return frames_; }
    double renderSeconds() const { return renderSeconds_; }
    double roundSeconds() const { return secondsBetween(roundStartedAt_, Clock::now()); }
    // The report's first-frame and rest times (nothing when no frame was rendered).
    void fill(SessionReport& report, Clock::time_point now = Clock::now()) const {
        if (frames_ == 0) return;
        report.firstFrameSeconds = secondsBetween(roundStartedAt_, firstFrameEndedAt_);
        report.pausedSeconds = pausedSeconds_;
        report.restSeconds = std::max(0.0, secondsBetween(firstFrameEndedAt_, now) - pausedSeconds_);
    }

private:
    Clock::time_point startedAt_ = Clock::now(), roundStartedAt_ = startedAt_, firstFrameEndedAt_ = startedAt_;
    int frames_ = 0;
    double renderSeconds_ = 0;
    double pausedSeconds_ = 0;
};

}  // namespace toyhost
