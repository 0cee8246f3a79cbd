// SessionCore: one shadertoy running, and the loop every way of running it shares: frames until the
// run's count, the driver's end or a stop, each one stepped, captured (session/Recording.h),
// checkpointed and checked; hot reload with its one rule; the watchdog's view of the run; the
// report. What differs between ways of running it is a driver's (SessionDriver below): the clock
// and input (timing/Timeline.h headless, a real-time clock in a window), presenting, screenshots,
// a window's live reload and `--watch` rounds (drivers/). The Sound pass is session/SoundJob.h.
// Headless runs, windows, `--watch`, `toyhost sound`, the compatibility probe, the GL tests and the
// library's Session all run through it.
//
// The reload rule: a reload never restarts. Changed code is recompiled (a pass that fails keeps
// its last good program); a changed structure (passes, bindings, image contents) rebuilds the
// renderer and keeps the content of every buffer that still exists; iFrame and time go on.
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
#include "session/Reload.h"
#include "session/RoundClock.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"
#include "session/Watchdog.h"
#include "timing/FrameTime.h"

namespace toyhost {

class SessionCore;
class Recording;
class TiledStill;
class BackgroundWriter;
class FiniteCheck;
class TemporaryFiles;
class Timeline;

// What differs between ways of running a session (SessionCore::run()).
class SessionDriver {
public:
    virtual ~SessionDriver() = default;
    // Before every frame: window events, controls (restart, pause, screenshot, resize), a live
    // reload. False ends the run as complete (the window was closed).
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
    // Nothing to render now (paused, or waiting for a shadertoy that compiles): wait a little for
    // events, showing what should be shown.
    virtual void idle(SessionCore& session) { (void)session; }
    // A new --watch round starts at frame 0: the clock and input scripts start over.
    virtual void restart() {}
    // The run stands paused (a window's pause): its idle time is not frame time in the report.
    virtual bool paused() const { return false; }
};

class SessionCore {
public:
    // Starts `plan` (prepareSession's) on `context`, made current here: compiles every pass,
    // renders a video's sound track, restores a --resume checkpoint. A shadertoy that does not
    // compile is an error, except in a window or with --watch, where the session starts without it
    // and waits for the fix (running() is false and problems() says why). `watchdog` may be null:
    // no limits, and stops come only from requestStop().
    static Result<std::unique_ptr<SessionCore>> start(SessionPlan plan, std::shared_ptr<GlContext> context,
                                                      SessionObserver& observer, Watchdog* watchdog = nullptr);
    ~SessionCore();
    SessionCore(const SessionCore&) = delete;
    SessionCore& operator=(const SessionCore&) = delete;

    // One round of the loop: frames from the first (or the checkpoint's) until the run's frame
    // count, the driver's end or a stop. Ends with the report, or the error that ended the run
    // (Code::Interrupted after a signal or requestStop: image files already written stay, a video
    // being encoded is discarded).
    Result<SessionReport> run(SessionDriver& driver);
    // A next round (`--watch`) is being prepared: its start-up time (reload, recompile) counts
    // from here.
    void beginNextRound();
    const SessionReport& report() const { return report_; }

    // `toyhost sound`: renders the Sound pass (options.sound) and writes the audio file.
    Result<SessionReport> writeSound();
    // The Sound pass as interleaved stereo samples at 44100 Hz, `seconds` long (0: 180 s).
    Result<std::vector<float>> renderSound(double seconds);

    // --- the building blocks run() is made of (for programs that own their loop) ---
    // Renders the run's next frame with `time` and `events` (captured, checkpointed and checked
    // as the options say); frames before a --frame-range are simulated (simulateFrame) without
    // rendering Image.
    Status renderFrame(const FrameTime& time, std::span<const InputEvent> events);
    // The library's Session::seek: frames simulated (simulateFrame) until iFrame `frame` is the
    // next, each at `timeline`'s time with its scripted events, as step() would have rendered
    // them. A frame before frame() is a Code::Usage error.
    Status seek(int frame, Timeline& timeline);
    // Applies `plan` (the shadertoy loaded and planned again after `changed` changed, or why it
    // could not be) with the reload rule above; a notice says what it did.
    ReloadOutcome reload(std::vector<std::filesystem::path> changed, Result<PlayerPlan> plan);
    // A paused window after a reload: the shown frame rendered again at `time` with the code that
    // runs now (Player::repaint: same iFrame, buffers one more step). Not captured, not checkpointed
    // and not counted as a frame of the run. False when no frame was shown yet (or none runs).
    bool repaint(const FrameTime& time) { return player_ && player_->repaint(time); }
    // A recording of the next frames of a session that records nothing (the library's
    // Session::record): `recording` is planRecording()'s plan (its output, frames, capture-every
    // and pass, frames numbered from 0 as a run's). renderFrame captures into it; endRecording()
    // waits for the encoders and gives the files written (a video: one); abandonRecording()
    // drops what is unfinished (an unfinished video is removed) and says what it left.
    Status beginRecording(SessionPlan recording);
    Result<std::vector<std::filesystem::path>> endRecording();
    std::string abandonRecording();
    // iFrame back to 0 and every buffer cleared (the site's restart); the driver resets its clock.
    void restart() {
        if (player_) player_->restart();
    }
    // New canvas size (window resize); buffers keep their content bottom-left.
    Status resize(int width, int height) { return player_ ? player_->resize(width, height) : okStatus(); }
    // Asks the run to stop before its next frame (any thread).
    void requestStop(StopReason reason = StopReason::Request) { stop_.request(reason); }
    bool stopRequested() const { return stop_.requested(); }

    // False while waiting for a shadertoy that compiles (window, --watch).
    bool running() const { return player_ != nullptr; }
    // The latest problems of the shadertoy (compile errors, a reload that failed); empty when
    // everything in its files runs.
    const std::vector<Diagnostic>& problems() const { return problems_; }
    const SessionPlan& plan() const { return plan_; }
    const std::string& name() const { return name_; }
    // The run's number of the next frame (what capture files are numbered by).
    int frameNumber() const { return frameNumber_; }
    GlContext& context() { return *context_; }

    // --- the running shadertoy (running() must be true) ---
    int frame() const { return player_->frame(); }  // iFrame of the next frame
    int width() const { return player_->width(); }
    int height() const { return player_->height(); }
    const ManifestDesc& manifest() const { return player_->manifest(); }
    PassOutput output(PassId pass) const { return player_->output(pass); }
    void readRgba8(PassId pass, std::vector<std::uint8_t>& out) const { player_->readRgba8(pass, out); }
    void readRgba32f(PassId pass, std::vector<float>& out) const { player_->readRgba32f(pass, out); }
    // iMouse as the next frame sees it.
    glm::vec4 mouse() const { return player_->mouse().uniform(); }
    // Waits for the GPU (the watchdog sees which pass it still draws).
    void finish() { player_->finish(); }
    // Submits the frame just rendered without waiting for it (Player::submit): the GPU works on it
    // while the caller goes on. The library's step() does, after each frame.
    void submit() { player_->submit(); }
    // Image drawn into a framebuffer that is not toyhost's (0: the default one) at x, y, w, h
    // (bottom-left origin; linear filtering when the size differs); GL's error if the copy made one.
    Status drawImage(unsigned int framebuffer, int x, int y, int w, int h) const;
    // A program's pixels in a channel from the next frame on (Player::setChannelArray).
    Status setChannelArray(PassId pass, int channel, const PixelArray& pixels, const SamplerDesc& sampler) {
        return player_->setChannelArray(pass, channel, pixels, sampler);
    }

private:
    friend struct SessionCoreAccess;  // tests: the Player itself
    SessionCore(SessionPlan plan, std::shared_ptr<GlContext> context, SessionObserver& observer, Watchdog* watchdog);
    Status createPlayer(PlayerPlan shadertoy);
    // The next frame simulated as the frames before a --frame-range are: buffers and Cube A run
    // (their state carries over) and Image is not rendered (unless it may discard: then it keeps
    // earlier frames' pixels, and is drawn); a shadertoy without them only advances its inputs and
    // counters. Nothing is captured or checked.
    void simulateFrame(const FrameTime& time, std::span<const InputEvent> events);
    Result<SessionReport> finishRound();
    Error interrupted();
    bool quitRequested() { return stop_.quitRequested(); }
    Status saveCheckpoint();
    void checkBuffers(int frame);
    Status beginRound();
    RunActivity* activity();

    SessionPlan plan_;
    std::shared_ptr<GlContext> context_;  // declared before everything that holds GL objects
    SessionObserver& observer_;
    Watchdog* watchdog_;
    SessionStop stop_;  // the one stop state (the watchdog's, when there is one)
    std::string name_;
    std::unique_ptr<BackgroundWriter> writer_;
    std::unique_ptr<Player> player_;
    std::unique_ptr<Recording> recording_;
    std::unique_ptr<TiledStill> tiled_;  // a canvas drawn in tiles (instead of recording_)
    std::unique_ptr<FiniteCheck> finite_;
    std::vector<Diagnostic> problems_;
    std::vector<InputEvent> events_;
    std::vector<float> bufferPixels_;
    bool imageKeepsPixels_ = false;  // the Image may discard: drawn on every frame (shader/ImageCoverage.h)
    bool live_ = false;          // a window: frames without an end, waiting for a shadertoy that compiles
    int frameNumber_ = 0;
    RoundClock clock_;  // this round's counts and times
    SessionReport report_;
    std::optional<std::filesystem::path> checkpointWritten_;
    std::shared_ptr<TemporaryFiles> soundTrack_;  // a video's sound track, while ffmpeg reads it
};

}  // namespace toyhost
