#include "drivers/headless/HeadlessDriver.h"

#include "gl/HeadlessContext.h"
#include "session/CompileProblems.h"
#include "session/ShadertoyWatcher.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <thread>

namespace toyhost {

HeadlessDriver::HeadlessDriver(const SessionPlan& plan) : timeline_(timelineOf(plan)) {
    if (plan.options.paced) pacer_.emplace(timeline_.fps());
}

// A resumed run starts at its checkpoint's frame: the scripts' earlier events are already in the
// saved mouse and keyboard state, so the timeline replays and drops them.
std::optional<FrameTime> HeadlessDriver::nextFrame(int frame, std::vector<InputEvent>& events) {
    if (pacer_) {
        if (pacer_->wait(monotonicNow()) > 0) return std::nullopt;  // not due yet: idle() waits
        pacer_->drawn(monotonicNow());
    }
    return timeline_.next(frame, events);
}

// --paced, before a frame is due: a wait in slices of at most 50 ms, so that a stop (a signal, the
// watchdog) ends the run at once whatever the rate.
void HeadlessDriver::idle(SessionCore&) {
    if (!pacer_) return;
    const double wait = std::min(pacer_->wait(monotonicNow()), 0.05);
    if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
}

void HeadlessDriver::restart() {
    timeline_.restart();
    if (pacer_) pacer_->reset();
}

namespace {

// --watch: the run's frames, then after every change of the shadertoy's files the frames again
// from frame 0 with what changed rebuilt, until a stop. A round's files are complete before the
// next begins.
Result<SessionReport> runWatchRounds(SessionCore& session, HeadlessDriver& driver, ShadertoyWatcher& watcher,
                                     SessionObserver& observer, Watchdog* watchdog) {
    Result<SessionReport> round = session.run(driver);
    auto stop = [&] { return session.stopRequested(); };
    while (true) {
        if (!round && round.error().category() == Category::Interrupted) return round;
        observer.roundFinished(round);
        std::optional<ShadertoyChange> change;
        while (!(change = watcher.wait(stop))) {
            // Stopped while waiting: the last round's files are complete. Ctrl-C is how a --watch
            // run is ended (exit 0); SIGTERM still says the run was terminated.
            if (!session.stopRequested()) continue;
            if (watchdog && watchdog->stop().reason == StopReason::Signal && watchdog->stop().signal == SIGINT)
                return round ? round : Result<SessionReport>(session.report());
            return Error("interrupted while watching the shadertoy's files; every round's files are complete",
                         Code::Interrupted);
        }
        session.beginNextRound();  // the start-up of the next round: reloading and recompiling
        ReloadOutcome outcome = session.reload(std::move(change->files), std::move(change->plan));
        // The reload's notice said what changed and whether the frames are rendered again.
        if (!session.running() || (!outcome.applied && !outcome.problems.empty())) {
            round = Error(outcome.problems.empty() ? session.problems() : outcome.problems);
            continue;
        }
        session.restart();
        driver.restart();
        round = session.run(driver);
    }
}

}  // namespace

Result<SessionReport> runHeadless(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog) {
    Result<SessionPlan> prepared = prepareSession(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    HeadlessOptions headless;
    headless.platform = prepared->options.eglPlatform;
    Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headless);
    if (!context) return context.error();
    std::optional<ShadertoyWatcher> watcher;
    if (prepared->options.watch)
        watcher.emplace(prepared->options.target, prepared->media, prepared->defines, prepared->shadertoy.manifest);
    Result<std::unique_ptr<SessionCore>> session = SessionCore::start(std::move(*prepared), *context, observer, watchdog);
    if (!session) return session.error();
    if (options.sound) return (*session)->writeSound();
    HeadlessDriver driver((*session)->plan());
    if (watcher) return runWatchRounds(**session, driver, *watcher, observer, watchdog);
    return (*session)->run(driver);
}

}  // namespace toyhost
