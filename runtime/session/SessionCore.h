// SessionCore: one shadertoy running, with everything around it that every way of running it shares:
// the Player (the engine), the recorder (--out), checkpoints, the finite-value checks, hot reload
// with its one rule, the watchdog (compiling, drawing, and writing the last frames), stopping
// (signals, a closed window, an API call) and the report. A driver brings only what differs (a
// clock, input events, and whether and where to present: SessionDriver below); headless runs,
// windows, `--watch`, `toyhost sound`, the compatibility probe and the GL tests all run through
// it, and so do programs that embed toyhost.
//
// The reload rule: a reload never restarts. Changed code is recompiled (a pass that fails keeps
// its last good program); a changed structure (passes, bindings, image contents) rebuilds the
// renderer and keeps the content of every buffer that still exists; iFrame and time go on. A
// --watch round renders the run's frames 0..N-1, so each round starts from frame 0 (a restart
// by definition of a round, not a consequence of the reload).
//
// Needs the GL context it is given current on the calling thread for its whole life (the GL
// thread: gl/GlThread.h).
#pragma once

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/Result.h"
#include "gl/GlContext.h"
#include "input/InputEvent.h"
#include "player/Player.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"
#include "timing/FrameTime.h"

namespace toyhost {

class SessionCore;
class FrameRecorder;
class BackgroundWriter;
class FiniteCheck;
class ShadertoyWatcher;
class TemporaryFiles;

// What differs between ways of running a session (session/SessionCore.h's run()).
class SessionDriver {
public:
    virtual ~SessionDriver() = default;
    // Before every frame: window events, controls (restart, pause, screenshot, resize). False ends
    // the run as complete (the window was closed).
    virtual bool poll(SessionCore& session) {
        (void)session;
        return true;
    }
    // The time of frame `frame` (the run's frame number: iFrame for headless runs, frames rendered
    // since the window opened for a window) with the input events that come before it appended to
    // `events`; nothing when no frame is due now (a paused window). Called once per frame, in order.
    virtual std::optional<FrameTime> nextFrame(int frame, std::vector<InputEvent>& events) = 0;
    // After a frame was rendered.
    virtual void present(SessionCore& session) { (void)session; }
    // Nothing to render now (paused, or waiting for a shader that compiles): wait a little for
    // events, showing what should be shown.
    virtual void idle(SessionCore& session) { (void)session; }
    // A new --watch round starts at frame 0: the clock and input scripts start over.
    virtual void restart() {}
};

// What a hot reload did.
struct ReloadOutcome {
    std::vector<std::filesystem::path> changed;  // the files that changed
    bool applied = false;            // new code or structure runs now
    bool structureChanged = false;
    std::vector<std::string> recompiled;  // passes whose new code runs
    // Empty when everything the files say runs now; else what does not (a pass that does not
    // compile keeps its last good program; a manifest that does not load keeps the old one).
    std::vector<Diagnostic> problems;
};

class SessionCore {
public:
    // Starts `plan` (prepareSession's) on `context`, made current here: compiles every pass,
    // creates the recorder, restores a --resume checkpoint. A shadertoy that does not compile is an
    // error, except in a window or with --watch, where the session starts without it and waits for
    // the fix (running() is false and problems() says why). `watchdog` may be null: no limits, and
    // stops come only from requestStop().
    static Result<std::unique_ptr<SessionCore>> start(SessionPlan plan, std::shared_ptr<GlContext> context,
                                                  SessionObserver& observer, Watchdog* watchdog = nullptr);
    ~SessionCore();
    SessionCore(const SessionCore&) = delete;
    SessionCore& operator=(const SessionCore&) = delete;

    // The loop every driver shares: frames until the run's frame count, the driver's end or a
    // stop; hot reload in a window; --watch rounds. Ends with the report, or the error that ended
    // the run (Code::Interrupted after a signal or requestStop: image files already written stay,
    // a video being encoded is discarded).
    Result<SessionReport> run(SessionDriver& driver);

    // `toyhost sound`: renders the Sound pass (options.sound) and writes the audio file.
    Result<SessionReport> writeSound();
    // The Sound pass as interleaved stereo samples at 44100 Hz, `seconds` long (0: 180 s).
    Result<std::vector<float>> renderSound(double seconds);

    // --- the building blocks run() is made of (for programs that own their loop) ---
    // Renders the run's next frame with `time` and `events` (captured, checkpointed and checked
    // as the options say); frames before a --frame-range are simulated without rendering Image.
    Status renderFrame(const FrameTime& time, std::span<const InputEvent> events);
    // Applies what the file watcher loaded since the last call, if anything (window mode).
    std::optional<ReloadOutcome> reloadIfChanged();
    // Applies `plan` (the shadertoy loaded and planned again, or why it could not be) with the
    // reload rule above.
    ReloadOutcome reload(Result<PlayerPlan> plan) { return applyChange({}, std::move(plan)); }
    // iFrame back to 0 and every buffer cleared (the site's restart); the driver resets its clock.
    void restart();
    // New canvas size (window resize); buffers keep their content bottom-left.
    Status resize(int width, int height);
    // F12: the shown frame as NAME-YYYYMMDD-HHMMSS-frameN.png in --out's folder or the working
    // directory, written off the GL thread (a notice says where when it is written).
    Status screenshot();
    // Asks the run to stop before its next frame (any thread).
    void requestStop(StopReason reason = StopReason::Request);
    bool stopRequested() const;

    // False while waiting for a shadertoy that compiles (window, --watch).
    bool running() const { return player_ != nullptr; }
    // The latest problems of the shadertoy (compile errors, a reload that failed); empty when
    // everything in its files runs.
    const std::vector<Diagnostic>& problems() const { return problems_; }
    Player& player() { return *player_; }
    const Player& player() const { return *player_; }
    const SessionPlan& plan() const { return plan_; }
    const std::string& name() const { return name_; }
    // The run's number of the next frame (what capture files are numbered by).
    int frameNumber() const { return frameNumber_; }
    GlContext& context() { return *context_; }

private:
    SessionCore(SessionPlan plan, std::shared_ptr<GlContext> context, SessionObserver& observer, Watchdog* watchdog);
    Status createPlayer(PlayerPlan shadertoy);
    Status prepareSoundTrack();
    Result<SessionReport> runRound(SessionDriver& driver);
    Result<SessionReport> finishRound();
    Error interrupted();
    ReloadOutcome applyChange(std::vector<std::filesystem::path> changed, Result<PlayerPlan> plan);
    Status saveCheckpoint();
    void checkBuffers(int frame);
    void reportWrites();
    Status beginRound();
    Status createRecorder();
    RunActivity* activity();

    SessionPlan plan_;
    std::shared_ptr<GlContext> context_;  // declared before everything that holds GL objects
    SessionObserver& observer_;
    Watchdog* watchdog_;
    std::atomic<int> localStop_{0};  // a StopReason, without a watchdog
    std::string name_;
    std::unique_ptr<BackgroundWriter> writer_;
    std::unique_ptr<ShadertoyWatcher> watcher_;
    std::unique_ptr<Player> player_;
    std::unique_ptr<FrameRecorder> recorder_;
    std::unique_ptr<FiniteCheck> finite_;
    std::vector<Diagnostic> problems_;
    std::vector<InputEvent> events_;
    std::vector<float> bufferPixels_;
    std::vector<int> captured_;  // frame numbers captured this round
    bool live_ = false;          // hot reload between frames (a window)
    int frameNumber_ = 0;
    int framesRendered_ = 0;     // this round
    double renderSeconds_ = 0;   // this round: in the player's frame calls and GPU waits
    SessionReport report_;
    std::chrono::steady_clock::time_point startedAt_, roundStartedAt_, firstFrameEndedAt_;
    std::optional<std::filesystem::path> checkpointWritten_;
    std::shared_ptr<TemporaryFiles> soundTrack_;  // a video's sound track, while ffmpeg reads it
};

}  // namespace toyhost
