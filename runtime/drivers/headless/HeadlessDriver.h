// The headless driver: what a run without a window brings to a SessionCore (session/SessionCore.h):
// the run's fixed-step input (timing/Timeline.h: frame n at iTime = start + n / fps with the input
// scripts of --mouse, --mouse-script, --key-script replayed by frame number), so every headless run
// of the same options renders the same frames; with --paced (SessionOptions::paced) it draws them at
// fps frames per second of wall time (timing/FramePacer.h), the same frames. runHeadless is `toyhost run --headless` (and `--watch`)
// and `toyhost sound`. Needs no display; it makes its own EGL context on the calling thread (the
// GL thread, gl/GlThread.h).
#pragma once

#include <optional>
#include <vector>

#include "core/Result.h"
#include "session/SessionCore.h"
#include "timing/FramePacer.h"
#include "timing/Timeline.h"

namespace toyhost {

class HeadlessDriver final : public SessionDriver {
public:
    explicit HeadlessDriver(const SessionPlan& plan);
    std::optional<FrameTime> nextFrame(int frame, std::vector<InputEvent>& events) override;
    void idle(SessionCore& session) override;
    void restart() override;

private:
    Timeline timeline_;
    std::optional<FramePacer> pacer_;
};

// Prepares `options` (every check before GL), creates a headless EGL context and runs the session:
// frames, or the Sound pass to an audio file (options.sound). `watchdog` may be null.
Result<SessionReport> runHeadless(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog);

}  // namespace toyhost
