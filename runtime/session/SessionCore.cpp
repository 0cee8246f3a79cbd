#include "session/SessionCore.h"

#include "core/ByteText.h"
#include "core/TemporaryFiles.h"
#include "render/Present.h"
#include "session/BackgroundWriter.h"
#include "session/Checkpoint.h"
#include "session/FiniteCheck.h"
#include "session/Recording.h"
#include "session/TiledStill.h"
#include "session/SoundJob.h"
#include "shader/ImageCoverage.h"
#include "timing/Timeline.h"

namespace toyhost {

namespace fs = std::filesystem;

SessionCore::SessionCore(SessionPlan plan, std::shared_ptr<GlContext> context, SessionObserver& observer, Watchdog* watchdog)
    : plan_(std::move(plan)), context_(std::move(context)), observer_(observer), watchdog_(watchdog), stop_(watchdog) {
    // Everything that renders or waits on the context publishes there for the watchdog.
    if (context_) context_->gpuActivity().attach(activity(), watchdog_ && watchdog_->watchesDraws());
}

SessionCore::~SessionCore() {
    // GL objects go while their context is current; the recorder's encoders stop first.
    if (context_) (void)context_->makeCurrent();
    recording_.reset();
    player_.reset();
    if (context_) context_->gpuActivity().attach(nullptr, false);  // the watchdog may go first
}

RunActivity* SessionCore::activity() { return watchdog_ ? &watchdog_->activity() : nullptr; }

Result<std::unique_ptr<SessionCore>> SessionCore::start(SessionPlan plan, std::shared_ptr<GlContext> context,
                                                        SessionObserver& observer, Watchdog* watchdog) {
    if (!context) return Error("a session needs a GL context", Code::Internal);
    if (Status current = context->makeCurrent(); !current) return current.error();
    std::unique_ptr<SessionCore> s(new SessionCore(std::move(plan), std::move(context), observer, watchdog));
    const SessionOptions& o = s->plan_.options;
    s->clock_.startCommand(o.startedAt.value_or(RoundClock::Clock::now()));
    s->name_ = s->plan_.shadertoy.manifest.name;
    s->writer_ = std::make_unique<BackgroundWriter>();
    s->finite_ = std::make_unique<FiniteCheck>();
    s->events_.reserve(64);
    s->live_ = o.interactive;
    for (const Diagnostic& line : s->plan_.shadertoy.notices) observer.notice(line);
    s->report_.mode = o.interactive ? "in a window" : "headless";
    s->report_.samplesPerFrame = samplesPerFrame(s->plan_.sampling);
    s->report_.context = s->context_->describe();
    s->report_.interactive = o.interactive;
    s->report_.outputAsked = o.outPattern.has_value() || o.sound.has_value();
    s->report_.toStdout = s->plan_.output && !s->plan_.output->kind().toFile;
    if (o.sound) return s;  // `toyhost sound`: the Sound pass only

    SoundJob sound(*s->context_, *s->writer_, s->activity(), [core = s.get()] { return core->stopRequested(); });
    Result<std::shared_ptr<TemporaryFiles>> track = sound.soundTrack(s->plan_, observer);
    if (!track) return track.error();
    s->soundTrack_ = std::move(*track);
    if (s->plan_.tile) s->tiled_ = std::make_unique<TiledStill>(s->plan_);
    else if (s->plan_.output) s->recording_ = std::make_unique<Recording>(s->plan_, s->activity(), [core = s.get()] {
            return core->stopRequested() && !core->quitRequested();
        });
    PlayerPlan shadertoy = std::move(s->plan_.shadertoy);
    if (Status created = s->createPlayer(std::move(shadertoy)); !created) {
        // A window or --watch waits for the fix of a shadertoy that does not compile yet.
        if (!(o.interactive || o.watch) || created.error().category() != Category::Shader) return created.error();
        s->problems_ = created.error().diagnostics;
        if (o.interactive) observer.problems(s->problems_);  // --watch reports them as its first round
        return s;
    }
    if (s->plan_.resume)
        if (Status restored = s->player_->restoreState(s->plan_.resume->state); !restored)
            return inFile(o.resume->string(), restored.error());
    return s;
}

Status SessionCore::createPlayer(PlayerPlan shadertoy) {
    const SessionOptions& o = plan_.options;
    PlayerDesc desc;
    // A window's canvas is its framebuffer, except while recording (one size for the recording).
    desc.width = *o.settings.width;
    desc.height = *o.settings.height;
    if (plan_.tile) TiledStill::fitPlayer(desc, plan_);  // the targets are one tile
    desc.floatImage = o.settings.floatImage ||
                      (plan_.output && plan_.output->kind().floats && o.capturePass == PassId::Image);
    desc.sampling = plan_.sampling;
    Result<std::unique_ptr<Player>> made = Player::create(context_, std::move(shadertoy), desc);
    if (!made) return made.error();
    player_ = std::move(*made);
    imageKeepsPixels_ = imageMayKeepPixels(player_->manifest());
    name_ = player_->manifest().name;
    problems_.clear();
    for (const Diagnostic& compiled : player_->compileNotices()) observer_.notice(compiled);
    return okStatus();
}

Result<std::vector<float>> SessionCore::renderSound(double seconds) {
    SoundJob sound(*context_, *writer_, activity(), [this] { return stopRequested(); });
    // Once the Player runs, the shadertoy's plan is its.
    return sound.render(player_ ? player_->plan() : plan_.shadertoy, seconds);
}

Result<SessionReport> SessionCore::writeSound() {
    report_.name = name_;
    report_.startupSeconds = clock_.secondsSinceCommand();
    SoundJob sound(*context_, *writer_, activity(), [this] { return stopRequested(); });
    return sound.writeFile(plan_.shadertoy, *plan_.options.sound, report_);
}

Status SessionCore::beginRound() {
    frameNumber_ = plan_.resume && plan_.resume->state.frame > 0 ? plan_.resume->state.frame : 0;
    report_ = report_.nextRound();
    report_.startupSeconds = clock_.beginRound();
    // Each round writes its own files; a window that waits for a shadertoy begins on the first frame.
    return recording_ && player_ ? recording_->begin(*player_, observer_) : okStatus();
}

void SessionCore::beginNextRound() { clock_.startCommand(); }

Status SessionCore::renderFrame(const FrameTime& time, std::span<const InputEvent> events) {
    if (!player_) return Error("no shadertoy runs yet (it did not compile)", Code::Internal);
    const SessionOptions& o = plan_.options;
    const int frame = frameNumber_;
    auto checkpointDue = [&] { return o.checkpointEvery && (frame + 1) % *o.checkpointEvery == 0; };
    if (frame < plan_.first) {
        simulateFrame(time, events);
        if (checkpointDue()) return saveCheckpoint();
        return okStatus();
    }
    if (recording_ && !recording_->begun())
        if (Status begun = recording_->begin(*player_, observer_); !begun) return begun;
    // Nothing reads the Image pass but the driver: a run that captures renders it only on the frames
    // it captures (long simulations captured every K frames run at buffer speed). A window shows
    // it, and a run without --out renders every pass (a dry run, the render-only benchmark). An
    // Image that may `discard` leaves pixels as the previous frame drew them, as the site's
    // preserved canvas does, so it is drawn on every frame (shader/ImageCoverage.h).
    const int captureFrame = recording_ ? recording_->captureFrame(frame) : frame;
    const bool renderImage =
        !tiled_ && (live_ || !recording_ || imageKeepsPixels_ || recording_->needsImage(captureFrame));
    if (std::optional<double> startup = clock_.frameStarting()) report_.startupSeconds = *startup;
    clock_.timed([&] { player_->step(time, events, renderImage); });

    if (recording_)
        if (Status recorded = recording_->rendered(*player_, captureFrame); !recorded) return recorded;
    if (tiled_)
        if (Status drawn = tiled_->render(*player_, frame); !drawn) return drawn;
    if (o.checkFinite) checkBuffers(frame);
    // The first frame waits for the GPU once, so that its time is real.
    if (o.finishEachFrame || clock_.frames() == 0) clock_.timed([&] { player_->finish(); });
    clock_.frameDone();
    ++frameNumber_;
    if (checkpointDue())
        if (Status saved = saveCheckpoint(); !saved) return saved;
    RunProgress progress;
    progress.frames = *o.frames > 0 ? plan_.end - plan_.first : 0;
    progress.framesDone = clock_.frames();
    progress.seconds = clock_.roundSeconds();
    progress.bytesWritten = recording_ ? recording_->bytesWritten() : 0;
    progress.samplesPerFrame = report_.samplesPerFrame;
    observer_.progress(progress);
    return okStatus();
}

void SessionCore::simulateFrame(const FrameTime& time, std::span<const InputEvent> events) {
    // Buffers and Cube A must still run (their state carries over); a shadertoy without them only
    // needs its inputs and counters to advance. An Image that may discard keeps what earlier frames
    // drew (the site's canvas is preserved), so it is drawn on every frame, these included.
    if (imageKeepsPixels_ && !tiled_) player_->step(time, events, /*renderImage=*/true);
    else if (player_->manifest().hasStatefulPasses()) player_->step(time, events, /*renderImage=*/false);
    else player_->skipFrame(events);
    ++frameNumber_;
}

Status SessionCore::seek(int frame, Timeline& timeline) {
    if (!player_) return Error("no shadertoy runs yet (it did not compile)", Code::Internal);
    if (frame < player_->frame())
        return Error("seek: frame " + std::to_string(frame) + " is before the next frame (" +
                         std::to_string(player_->frame()) +
                         "): a session only goes forward (restart() goes back to frame 0)",
                     Code::Usage);
    while (player_->frame() < frame) {
        events_.clear();
        const FrameTime time = timeline.next(player_->frame(), events_);  // fills events_ first
        simulateFrame(time, events_);
    }
    return okStatus();
}

// Every buffer once: after every frame with --check-finite, else after the last one.
void SessionCore::checkBuffers(int frame) {
    const FiniteCheck::Coverage coverage =
        plan_.options.checkFinite ? FiniteCheck::Coverage::EveryFrame : FiniteCheck::Coverage::LastFrameOnly;
    for (const PassDesc& pass : player_->manifest().passes) {
        if (!isBuffer(pass.id) || finite_->reported(pass.id)) continue;
        player_->readRgba32f(pass.id, bufferPixels_);
        if (auto warning = finite_->check(pass.id, frame, bufferPixels_, player_->width(), coverage))
            observer_.notice(*warning);
    }
}

Status SessionCore::saveCheckpoint() {
    const SessionOptions& o = plan_.options;
    if (!o.checkpoint || !player_) return okStatus();
    Result<fs::path> written = writeCheckpointOffThread(
        *writer_, *o.checkpoint,
        Checkpoint{player_->saveState(), *o.settings.fps, o.settings.startTime, *plan_.wallClock, player_->manifest().name,
                   codeHash(player_->manifest(), plan_.defines), channelMedia(player_->manifest())});
    if (!written) return written.error();
    checkpointWritten_ = *written;
    return okStatus();
}

Status SessionCore::drawImage(unsigned int framebuffer, int x, int y, int w, int h) const {
    return drawOutput(player_->output(PassId::Image), framebuffer, PresentRect{x, y, w, h});
}

ReloadOutcome SessionCore::reload(std::vector<fs::path> changed, Result<PlayerPlan> plan) {
    ReloadOutcome outcome;
    outcome.changed = std::move(changed);
    if (!plan) {
        outcome.problems = plan.error().diagnostics;
    } else if (!player_) {
        if (Status created = createPlayer(std::move(*plan)); !created) {
            outcome.problems = created.error().diagnostics;
        } else {
            outcome.applied = outcome.structureChanged = true;
            for (const PassDesc& pass : player_->manifest().passes) outcome.recompiled.push_back(passName(pass.id));
        }
    } else {
        ReloadReport reloaded = player_->reload(std::move(*plan));
        outcome.applied = reloaded.applied;
        outcome.structureChanged = reloaded.structureChanged;
        outcome.recompiled = std::move(reloaded.recompiled);
        outcome.problems = std::move(reloaded.problems);
        name_ = player_->manifest().name;
        for (const Diagnostic& compiled : player_->compileNotices()) observer_.notice(compiled);
    }
    // The problems shown are those of the files as they are now: a change that leaves nothing
    // failing (an undone mistake whose code equals what runs) clears them.
    problems_ = outcome.problems;
    // A --watch round reports its problems itself when it ends (SessionObserver::roundFinished):
    // said here too, each would be printed twice.
    const bool watch = plan_.options.watch;
    observer_.notice(describeReload(outcome, watch ? std::optional<int>(std::max(0, plan_.end - plan_.first)) : std::nullopt));
    if (!outcome.problems.empty() && !watch) observer_.problems(outcome.problems);
    return outcome;
}

Error SessionCore::interrupted() {
    const int frame = frameNumber_;
    std::string message = frame < plan_.end || plan_.end == 0 ? "interrupted after " + plural(clock_.frames(), "frame")
                                                              : "interrupted while the last captured frames were written";
    if (plan_.end > 0 && frame < plan_.end) message += " of " + std::to_string(plan_.end - plan_.first);
    (void)saveCheckpoint();  // best effort: the run is ending anyway
    if (checkpointWritten_) message += "; the checkpoint " + checkpointWritten_->string() + " was written";
    if (recording_) message += recording_->abandon();
    if (tiled_) message += tiled_->abandon();
    return Error(message, Code::Interrupted);
}

Result<SessionReport> SessionCore::finishRound() {
    const SessionOptions& o = plan_.options;
    report_.name = name_;
    report_.frames = clock_.frames();
    if (recording_ && recording_->begun()) {
        Status completed = recording_->complete();
        // A signal during the final writes still ends the run as interrupted (exit 130/143),
        // whatever the encoders managed; an interrupted video is discarded even if it was just
        // completed, as every interrupted video is.
        if (stopRequested() && !quitRequested()) {
            if (completed) recording_->discardVideo();
            return interrupted();
        }
        if (!completed) return completed.error();
        recording_->report(report_, clock_.renderSeconds(), observer_, *finite_);
    }
    if (Status written = tiled_ ? tiled_->complete() : okStatus(); !written) return written.error();
    if (tiled_) tiled_->report(report_);
    if (player_ && !o.checkFinite && clock_.frames() > 0) checkBuffers(frameNumber_ - 1);
    if (!o.interactive)
        if (Status saved = saveCheckpoint(); !saved) return saved.error();
    writer_->drain();
    if (player_) player_->finish();  // the reported time includes the GPU's work
    report_.checkpoint = checkpointWritten_;
    report_.width = player_ && !plan_.tile ? player_->width() : *o.settings.width;
    report_.height = player_ && !plan_.tile ? player_->height() : *o.settings.height;
    clock_.fill(report_);
    return report_;
}

Status SessionCore::beginRecording(SessionPlan recording) {
    if (!player_) return Error("no shadertoy runs yet (it did not compile)", Code::Internal);
    if (recording_ || tiled_) return Error("this session records already", Code::Usage);
    Result<std::unique_ptr<Recording>> begun = Recording::ofNextFrames(
        std::move(recording), frameNumber_, activity(), [this] { return stopRequested(); }, *player_, observer_);
    if (!begun) return begun.error();
    recording_ = std::move(*begun);
    return okStatus();
}

Result<std::vector<fs::path>> SessionCore::endRecording() {
    if (!recording_) return Error("no recording to end", Code::Internal);
    Result<std::vector<fs::path>> files = recording_->end(clock_.renderSeconds(), observer_, *finite_);
    recording_.reset();
    return files;
}

std::string SessionCore::abandonRecording() {
    if (!recording_) return {};
    std::string left = recording_->abandon();
    recording_->discardVideo();
    recording_.reset();
    return left;
}

Result<SessionReport> SessionCore::run(SessionDriver& driver) {
    // Headless, a shadertoy that does not compile has nothing to run (--watch waits for a change
    // in its driver); a window waits in its loop.
    if (!player_ && !live_) return Error(problems_);
    if (Status begun = beginRound(); !begun) return begun.error();
    while (true) {
        if (stopRequested()) {
            if (quitRequested()) break;
            return interrupted();
        }
        if (!driver.poll(*this)) break;
        if (plan_.end > 0 && frameNumber_ >= plan_.end) break;
        if (!player_) {
            driver.idle(*this);
            continue;
        }
        events_.clear();
        std::optional<FrameTime> time = driver.nextFrame(frameNumber_, events_);
        if (!time) {
            clock_.idle(driver.paused(), [&] { driver.idle(*this); });
            continue;
        }
        if (Status rendered = renderFrame(*time, events_); !rendered) {
            // A stop that ended a wait for the encoders is the stop, not a capture failure.
            if (rendered.error().first().code == Code::CaptureStopped && stopRequested() && !quitRequested())
                return interrupted();
            return rendered.error();
        }
        driver.present(*this);
    }
    return finishRound();
}

}  // namespace toyhost
