#include "drivers/headless/HeadlessDriver.h"

#include "gl/HeadlessContext.h"
#include "session/AllProblems.h"

namespace toyhost {

HeadlessDriver::HeadlessDriver(const SessionPlan& plan)
    : plan_(plan), clock_(*plan.options.fps, plan.options.startTime, *plan.options.wallClock), mouse_(plan.mouse),
      keys_(plan.keys) {}

std::optional<FrameTime> HeadlessDriver::nextFrame(int frame, std::vector<InputEvent>& events) {
    // A resumed run starts at its checkpoint's frame: the scripts' earlier events are already in
    // the saved mouse and keyboard state, so they are replayed and dropped.
    std::vector<InputEvent> earlier;
    for (; next_ < frame; ++next_) {
        earlier.clear();
        mouse_.eventsBeforeFrame(next_, clock_.time(next_), earlier);
        keys_.eventsBeforeFrame(next_, clock_.time(next_), earlier);
    }
    const double time = clock_.time(frame);
    mouse_.eventsBeforeFrame(frame, time, events);
    keys_.eventsBeforeFrame(frame, time, events);
    next_ = frame + 1;
    return clock_.frameTime(frame);
}

void HeadlessDriver::restart() {
    mouse_ = MouseScriptPlayer(plan_.mouse);
    keys_ = KeyScriptPlayer(plan_.keys);
    next_ = 0;
}

Result<SessionReport> runHeadless(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog) {
    Result<SessionPlan> prepared = prepareSession(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    HeadlessOptions headless;
    headless.platform = prepared->options.eglPlatform;
    Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headless);
    if (!context) return context.error();
    Result<std::unique_ptr<SessionCore>> session = SessionCore::start(std::move(*prepared), *context, observer, watchdog);
    if (!session) return session.error();
    if (options.sound) return (*session)->writeSound();
    HeadlessDriver driver((*session)->plan());
    return (*session)->run(driver);
}

}  // namespace toyhost
