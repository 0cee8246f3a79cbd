#include "session/SessionCore.h"

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "capture/WavFile.h"
#include "core/Defaults.h"
#include "core/TemporaryFiles.h"
#include "image/ImageWriters.h"
#include "session/BackgroundWriter.h"
#include "session/Checkpoint.h"
#include "session/FiniteCheck.h"
#include "session/FrameRecorder.h"
#include "session/ShadertoyWatcher.h"
#include "capture/SoundFile.h"
#include "render/SoundRenderer.h"

namespace toyhost {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

double secondsBetween(Clock::time_point from, Clock::time_point to) {
    return std::chrono::duration<double>(to - from).count();
}

Diagnostic notice(std::string message, Code code, std::string file = {}) {
    Diagnostic d;
    d.severity = Severity::Notice;
    d.code = code;
    d.message = std::move(message);
    d.file = std::move(file);
    return d;
}

std::string plural(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

std::string fileSafe(std::string name) {
    for (char& c : name)
        if (c == '/' || c == '\\' || c == ':' || static_cast<unsigned char>(c) < 32) c = '_';
    return name.empty() ? std::string("toyhost") : name;
}

bool hasBuffers(const ManifestDesc& manifest) {
    for (const PassDesc& pass : manifest.passes)
        if (isBuffer(pass.id)) return true;
    return false;
}

}  // namespace

SessionCore::SessionCore(SessionPlan plan, std::shared_ptr<GlContext> context, SessionObserver& observer, Watchdog* watchdog)
    : plan_(std::move(plan)), context_(std::move(context)), observer_(observer), watchdog_(watchdog) {
    // Everything that renders or waits on the context publishes there for the watchdog.
    if (context_) context_->gpuActivity().attach(activity(), watchdog_ && watchdog_->watchesDraws());
}

SessionCore::~SessionCore() {
    // GL objects go while their context is current; the recorder's encoders stop first.
    if (context_) (void)context_->makeCurrent();
    recorder_.reset();
    player_.reset();
    if (context_) context_->gpuActivity().attach(nullptr, false);  // the watchdog may go first
}

RunActivity* SessionCore::activity() { return watchdog_ ? &watchdog_->activity() : nullptr; }

void SessionCore::requestStop(StopReason reason) {
    if (watchdog_) watchdog_->requestStop(reason);
    else localStop_.store(static_cast<int>(reason));
}

bool SessionCore::stopRequested() const {
    return watchdog_ ? watchdog_->stopRequested() : localStop_.load() != static_cast<int>(StopReason::None);
}

Result<std::unique_ptr<SessionCore>> SessionCore::start(SessionPlan plan, std::shared_ptr<GlContext> context,
                                                SessionObserver& observer, Watchdog* watchdog) {
    if (!context) return Error("a session needs a GL context", Code::Internal);
    if (Status current = context->makeCurrent(); !current) return current.error();
    std::unique_ptr<SessionCore> s(new SessionCore(std::move(plan), std::move(context), observer, watchdog));
    const SessionOptions& o = s->plan_.options;
    s->startedAt_ = o.startedAt.value_or(Clock::now());
    s->name_ = s->plan_.shadertoy.manifest.name;
    s->writer_ = std::make_unique<BackgroundWriter>();
    s->finite_ = std::make_unique<FiniteCheck>();
    s->events_.reserve(64);
    s->live_ = o.interactive;
    for (const Diagnostic& line : s->plan_.shadertoy.notices) observer.notice(line);
    s->report_.mode = o.interactive ? "in a window" : "headless";
    s->report_.context = s->context_->describe();
    s->report_.interactive = o.interactive;
    s->report_.outputAsked = o.outPattern.has_value() || o.sound.has_value();
    s->report_.toStdout = s->plan_.output && s->plan_.output->format() == OutputFormat::RawStream;
    if (o.sound) return s;  // `toyhost sound`: the Sound pass only

    if (o.interactive || o.watch)
        s->watcher_ = std::make_unique<ShadertoyWatcher>(o.target, o.media, s->plan_.shadertoy.manifest);
    if (Status sound = s->prepareSoundTrack(); !sound) return sound.error();
    PlayerPlan shadertoy = std::move(s->plan_.shadertoy);
    if (Status created = s->createPlayer(std::move(shadertoy)); !created) {
        // A window or --watch waits for the fix of a shadertoy that does not compile yet.
        if (!s->watcher_ || created.error().category() != Category::Shader) return created.error();
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
    desc.width = *o.width;
    desc.height = *o.height;
    desc.floatImage = o.floatImage || (plan_.output && plan_.output->format() == OutputFormat::Exr &&
                                       o.capturePass == PassId::Image);
    Result<std::unique_ptr<Player>> made = Player::create(context_, std::move(shadertoy), desc);
    if (!made) return made.error();
    player_ = std::move(*made);
    name_ = player_->manifest().name;
    problems_.clear();
    for (const Diagnostic& compiled : player_->compileNotices()) observer_.notice(compiled);
    return okStatus();
}

Status SessionCore::createRecorder() {
    if (!plan_.output || recorder_ || !player_) return okStatus();
    Result<std::unique_ptr<FrameRecorder>> created = FrameRecorder::create(recorderSettings(plan_, activity()), *player_);
    if (!created) return created.error();
    recorder_ = std::move(*created);
    if (!recorder_->videoEncoderChoice().empty())
        observer_.notice(notice(recorder_->videoEncoderChoice(), Code::CaptureFfmpeg));
    return okStatus();
}

// The Sound pass of a shadertoy whose video output carries sound: rendered up front, from the
// run's start time, and written as the video's sound track; other outputs carry no sound.
Status SessionCore::prepareSoundTrack() {
    const SessionOptions& o = plan_.options;
    const ManifestDesc& manifest = plan_.shadertoy.manifest;
    if (!manifest.sound) return okStatus();
    const bool video = plan_.output && plan_.output->format() == OutputFormat::Video;
    const double fps = o.fps.value_or(defaults::kFps);
    const double end = std::min(o.startTime + *o.frames / fps, defaults::kSoundSeconds);
    if (!video || *o.frames <= 0 || end <= o.startTime) {
        Diagnostic skipped = notice(video ? "the Sound pass ends at 180 s, before this run starts: the video has no sound"
                                          : "the Sound pass is not rendered: only a video --out (.mp4, .webm, .mov, "
                                            ".mkv) carries sound; `toyhost sound` writes it to an audio file",
                                    Code::SoundSkipped);
        skipped.pass = "Sound";
        observer_.notice(skipped);
        return okStatus();
    }
    Result<std::vector<float>> stereo = renderSound(end);
    if (!stereo) return stereo.error();
    const std::size_t skip =
        std::min(stereo->size(), 2 * static_cast<std::size_t>(std::llround(o.startTime * defaults::kSampleRate)));
    auto track = std::make_shared<TemporaryFiles>("soundtrack", std::initializer_list<const char*>{"wav"});
    if (!track->registerAll()) return Error("not started: toyhost is stopping", Code::Interrupted);
    auto samples = std::make_shared<std::vector<float>>(stereo->begin() + static_cast<std::ptrdiff_t>(skip), stereo->end());
    writer_->submit([track, samples]() -> Result<fs::path> {
        if (Status wav = writeWav16((*track)[0], *samples, static_cast<int>(defaults::kSampleRate)); !wav)
            return wav.error();
        return (*track)[0];
    });
    writer_->drain();
    for (Result<fs::path>& written : writer_->takeFinished())
        if (!written) return written.error();
    soundTrack_ = track;
    plan_.options.video.audio = (*track)[0];
    return okStatus();
}

Result<std::vector<float>> SessionCore::renderSound(double seconds) {
    SoundRenderDesc desc;
    desc.seconds = seconds;
    desc.stopRequested = [this] { return stopRequested(); };
    // Once the Player runs, the shadertoy's plan is its.
    const PlayerPlan& shadertoy = player_ ? player_->plan() : plan_.shadertoy;
    if (shadertoy.soundSource) desc.source = &*shadertoy.soundSource;
    return toyhost::renderSound(*context_, shadertoy.manifest, shadertoy.images, desc);
}

Result<SessionReport> SessionCore::writeSound() {
    const SoundRequest& request = *plan_.options.sound;
    const double seconds = request.seconds > 0 ? request.seconds : defaults::kSoundSeconds;
    roundStartedAt_ = Clock::now();
    report_.startupSeconds = secondsBetween(startedAt_, roundStartedAt_);
    Result<std::vector<float>> stereo = renderSound(seconds);
    if (!stereo) return stereo.error();
    firstFrameEndedAt_ = Clock::now();
    if (stopRequested()) return Error("interrupted: no audio file was written", Code::Interrupted);
    auto samples = std::make_shared<std::vector<float>>(std::move(*stereo));
    const fs::path out = request.out;
    writer_->submit([out, samples]() -> Result<fs::path> {
        if (Status written = writeSoundFile(out, *samples); !written) return written.error();
        return out;
    });
    if (RunActivity* a = activity()) a->begin(RunActivity::Phase::WaitingForOutput);
    writer_->drain();
    if (RunActivity* a = activity()) a->idle();
    for (Result<fs::path>& written : writer_->takeFinished()) {
        if (!written) return written.error();
        if (*written == "-") report_.toStdout = true;
        else report_.files.push_back(*written);
    }
    report_.name = name_;
    report_.firstFrameSeconds = secondsBetween(roundStartedAt_, firstFrameEndedAt_);
    report_.restSeconds = secondsBetween(firstFrameEndedAt_, Clock::now());
    report_.soundSeconds = seconds;
    return report_;
}

Status SessionCore::beginRound() {
    frameNumber_ = plan_.resume && plan_.resume->state.frame > 0 ? plan_.resume->state.frame : 0;
    framesRendered_ = 0;
    renderSeconds_ = 0;
    captured_.clear();
    roundStartedAt_ = Clock::now();
    SessionReport fresh;
    fresh.mode = report_.mode;
    fresh.context = report_.context;
    fresh.interactive = report_.interactive;
    fresh.outputAsked = report_.outputAsked;
    fresh.toStdout = report_.toStdout;
    report_ = std::move(fresh);
    report_.startupSeconds = secondsBetween(startedAt_, roundStartedAt_);
    return createRecorder();  // each round writes its own files
}

Status SessionCore::renderFrame(const FrameTime& time, std::span<const InputEvent> events) {
    if (!player_) return Error("no shadertoy runs yet (it did not compile)", Code::Internal);
    const SessionOptions& o = plan_.options;
    const int frame = frameNumber_;
    auto checkpointDue = [&] { return o.checkpointEvery && (frame + 1) % *o.checkpointEvery == 0; };
    if (frame < plan_.first) {
        // Before the frame range: buffers must still run (their state carries over); a shadertoy
        // without buffers only needs its inputs and counters to advance.
        if (hasBuffers(player_->manifest())) player_->step(time, events, /*renderImage=*/false);
        else player_->skipFrame(events);
        ++frameNumber_;
        if (checkpointDue()) return saveCheckpoint();
        return okStatus();
    }
    const bool captured = recorder_ && isCapturedFrame(frame, *o.frames, *o.captureEvery);
    // Nothing reads the Image pass but the driver: a run that captures renders it only on the frames
    // it captures (long simulations captured every K frames run at buffer speed). A window shows
    // it, and a run without --out renders every pass (a dry run, the render-only benchmark).
    const bool renderImage = live_ || !recorder_ || (captured && o.capturePass == PassId::Image);
    if (framesRendered_ == 0) {
        roundStartedAt_ = Clock::now();
        report_.startupSeconds = secondsBetween(startedAt_, roundStartedAt_);
    }
    const Clock::time_point stepStarted = Clock::now();
    player_->step(time, events, renderImage);
    renderSeconds_ += secondsBetween(stepStarted, Clock::now());

    if (captured) {
        if (Status saved = recorder_->capture(*player_, frame); !saved) return saved;
        captured_.push_back(frame);
    } else if (recorder_) {
        if (Status polled = recorder_->poll(); !polled) return polled;
    }
    if (o.checkFinite) checkBuffers(frame);
    // The first frame waits for the GPU once, so that its time is real.
    if (o.finishEachFrame || framesRendered_ == 0) {
        const Clock::time_point finishStarted = Clock::now();
        player_->finish();
        renderSeconds_ += secondsBetween(finishStarted, Clock::now());
    }
    if (framesRendered_ == 0) firstFrameEndedAt_ = Clock::now();
    ++framesRendered_;
    ++frameNumber_;
    if (checkpointDue())
        if (Status saved = saveCheckpoint(); !saved) return saved;
    reportWrites();
    RunProgress progress;
    progress.frames = *o.frames > 0 ? plan_.end - plan_.first : 0;
    progress.framesDone = framesRendered_;
    progress.seconds = secondsBetween(roundStartedAt_, Clock::now());
    progress.bytesWritten = recorder_ ? recorder_->bytesWritten() : 0;
    observer_.progress(progress);
    return okStatus();
}

// Every buffer once: after every frame with --check-finite, else after the last one.
void SessionCore::checkBuffers(int frame) {
    const SessionOptions& o = plan_.options;
    for (const PassDesc& pass : player_->manifest().passes) {
        if (!isBuffer(pass.id) || finite_->reported(pass.id)) continue;
        player_->readRgba32f(pass.id, bufferPixels_);
        const FiniteCheck::Coverage coverage =
            o.checkFinite ? FiniteCheck::Coverage::EveryFrame : FiniteCheck::Coverage::LastFrameOnly;
        if (auto warning = finite_->check(pass.id, frame, bufferPixels_, player_->width(), coverage))
            observer_.notice(*warning);
    }
}

Status SessionCore::saveCheckpoint() {
    const SessionOptions& o = plan_.options;
    if (!o.checkpoint || !player_) return okStatus();
    const double wallClock = *o.wallClock;
    auto checkpoint = std::make_shared<Checkpoint>(Checkpoint{player_->saveState(), *o.fps, o.startTime, wallClock,
                                                              player_->manifest().name, codeHash(player_->manifest()),
                                                              channelMedia(player_->manifest())});
    const fs::path path = *o.checkpoint;
    writer_->submit([path, checkpoint]() -> Result<fs::path> {
        if (Status written = writeCheckpoint(path, *checkpoint); !written) return written.error();
        return path;
    });
    // The next checkpoint reads the buffers again: let this one be written first, so that at
    // most one copy of the state waits in memory.
    writer_->drain();
    for (Result<fs::path>& written : writer_->takeFinished()) {
        if (!written) return written.error();
        checkpointWritten_ = *written;
    }
    return okStatus();
}

void SessionCore::reportWrites() {
    for (Result<fs::path>& written : writer_->takeFinished()) {
        if (!written) {
            for (const Diagnostic& d : written.error().diagnostics) observer_.notice(d);
            continue;
        }
        observer_.notice(notice("screenshot written", Code::WindowScreenshot, written->string()));
    }
}

Status SessionCore::screenshot() {
    if (!player_ || framesRendered_ == 0) return Error("nothing is shown yet: no screenshot", Code::WindowScreenshot);
    const SessionOptions& o = plan_.options;
    fs::path folder = ".";
    if (plan_.output && (plan_.output->format() == OutputFormat::Png || plan_.output->format() == OutputFormat::Exr ||
                         plan_.output->format() == OutputFormat::Video)) {
        const fs::path parent = plan_.output->pathFor(0).parent_path();
        if (!parent.empty()) folder = parent;
    }
    (void)o;
    char stamp[32];
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    const std::string base = fileSafe(name_) + "-" + stamp + "-frame" + std::to_string(player_->frame() - 1);
    auto pixels = std::make_shared<std::vector<std::uint8_t>>();
    player_->readRgba8(PassId::Image, *pixels);
    const int width = player_->width(), height = player_->height();
    writer_->submit([folder, base, pixels, width, height]() -> Result<fs::path> {
        // Two screenshots of one frame in one second (after a restart) get their own names.
        fs::path file = folder / (base + ".png");
        std::error_code ec;
        for (int n = 2; fs::exists(file, ec); ++n) file = folder / (base + "-" + std::to_string(n) + ".png");
        if (Status written = writePng(file, width, height, *pixels); !written) return written.error();
        return file;
    });
    return okStatus();
}

void SessionCore::restart() {
    if (player_) player_->restart();
}

Status SessionCore::resize(int width, int height) {
    if (!player_) return okStatus();
    return player_->resize(width, height);
}

ReloadOutcome SessionCore::applyChange(std::vector<fs::path> changed, Result<PlayerPlan> plan) {
    ReloadOutcome outcome;
    outcome.changed = std::move(changed);
    if (!plan) {
        outcome.problems = plan.error().diagnostics;
    } else if (!player_) {
        if (Status created = createPlayer(std::move(*plan)); !created) {
            outcome.problems = created.error().diagnostics;
        } else if (Status recording = live_ ? createRecorder() : okStatus(); !recording) {
            outcome.problems = recording.error().diagnostics;
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

    std::string files;
    for (const fs::path& file : outcome.changed) files += (files.empty() ? "" : ", ") + file.filename().string();
    std::string what;
    if (!outcome.problems.empty()) what = outcome.applied ? "partly applied" : "not applied";
    else if (!outcome.applied) what = "nothing to recompile: what runs already matches the files";
    else {
        std::string passes;
        for (const std::string& pass : outcome.recompiled) passes += (passes.empty() ? "" : ", ") + pass;
        what = outcome.structureChanged ? "new structure (buffers that still exist keep their content): " + passes
                                        : "recompiled " + passes;
    }
    observer_.notice(notice((files.empty() ? std::string("the shadertoy") : files) + " changed: " + what, Code::WatchChanged));
    if (!outcome.problems.empty()) observer_.problems(outcome.problems);
    return outcome;
}

std::optional<ReloadOutcome> SessionCore::reloadIfChanged() {
    if (!watcher_) return std::nullopt;
    std::optional<ShadertoyChange> change = watcher_->take();
    if (!change) return std::nullopt;
    return applyChange(std::move(change->files), std::move(change->plan));
}

Error SessionCore::interrupted() {
    const int frame = frameNumber_;
    std::string message = frame < plan_.end || plan_.end == 0 ? "interrupted after " + plural(framesRendered_, "frame")
                                                              : "interrupted while the last captured frames were written";
    if (plan_.end > 0 && frame < plan_.end) message += " of " + std::to_string(plan_.end - plan_.first);
    (void)saveCheckpoint();  // best effort: the run is ending anyway
    if (checkpointWritten_) message += "; the checkpoint " + checkpointWritten_->string() + " was written";
    if (recorder_) {
        const FrameRecorder::Abandoned a = recorder_->abandon();
        switch (plan_.output->format()) {
            case OutputFormat::Video: message += "; the unfinished video was discarded"; break;
            case OutputFormat::RawStream: message += "; " + plural(a.written, "frame") + " went to stdout"; break;
            default: message += "; " + plural(a.written, "file") + " written"; break;
        }
        if (a.dropped > 0) message += ", " + plural(a.dropped, "captured frame") + " not written (dropped)";
    }
    return Error(message, Code::Interrupted);
}

Result<SessionReport> SessionCore::finishRound() {
    const SessionOptions& o = plan_.options;
    report_.name = name_;
    report_.frames = framesRendered_;
    if (recorder_) {
        Status finished = recorder_->finish();
        // A signal during the final writes still ends the run as interrupted (exit 130/143),
        // whatever the encoders managed; an interrupted video is discarded even if it was just
        // completed, as every interrupted video is.
        if (stopRequested() && (!watchdog_ || watchdog_->stop().reason != StopReason::Quit)) {
            if (finished && plan_.output->format() == OutputFormat::Video) {
                std::error_code ec;
                fs::remove(plan_.output->pathFor(0), ec);
            }
            return interrupted();
        }
        if (!finished) return finished.error();
        report_.bytesWritten = recorder_->bytesWritten();
        report_.encoderThreads = recorder_->encoderThreads();
        report_.videoEncoder = recorder_->videoEncoder();
        report_.captureTimes = CaptureTimes{renderSeconds_, recorder_->readbackSeconds(), recorder_->waitSeconds(),
                                            recorder_->encodeSeconds(), recorder_->writeSeconds()};
        if (const auto& nonFinite = recorder_->firstNonFinite())
            if (auto warning = finite_->check(o.capturePass, nonFinite->first, nonFinite->second,
                                              FiniteCheck::Coverage::CapturedFrames))
                observer_.notice(*warning);
        const std::vector<int>& dropped = recorder_->droppedFrames();
        if (!dropped.empty())
            observer_.notice(notice(plural(static_cast<int>(dropped.size()), "frame") +
                                        " were not recorded: the encoders were behind and real-time mode does not "
                                        "wait for them (use --fps for every frame)",
                                    Code::CaptureDropped));
        switch (plan_.output->format()) {
            case OutputFormat::Video: report_.files.push_back(plan_.output->pathFor(0)); break;
            case OutputFormat::RawStream: break;
            default:
                for (int frame : captured_)
                    if (std::find(dropped.begin(), dropped.end(), frame) == dropped.end())
                        report_.files.push_back(plan_.output->pathFor(frame));
        }
        recorder_.reset();  // complete; a next round has its own
    }
    if (player_ && !o.checkFinite && framesRendered_ > 0) checkBuffers(frameNumber_ - 1);
    if (!o.interactive)
        if (Status saved = saveCheckpoint(); !saved) return saved.error();
    writer_->drain();
    reportWrites();
    if (player_) player_->finish();  // the reported time includes the GPU's work
    report_.checkpoint = checkpointWritten_;
    report_.width = player_ ? player_->width() : *o.width;
    report_.height = player_ ? player_->height() : *o.height;
    const Clock::time_point end = Clock::now();
    if (framesRendered_ > 0) {
        report_.firstFrameSeconds = secondsBetween(roundStartedAt_, firstFrameEndedAt_);
        report_.restSeconds = secondsBetween(firstFrameEndedAt_, end);
    }
    return report_;
}

Result<SessionReport> SessionCore::runRound(SessionDriver& driver) {
    if (Status begun = beginRound(); !begun) return begun.error();
    while (true) {
        if (stopRequested()) {
            if (watchdog_ && watchdog_->stop().reason == StopReason::Quit) {
                watchdog_->quitHonoured();
                break;
            }
            if (localStop_.load() == static_cast<int>(StopReason::Quit)) break;
            return interrupted();
        }
        if (!driver.poll(*this)) break;
        if (live_) (void)reloadIfChanged();
        if (plan_.end > 0 && frameNumber_ >= plan_.end) break;
        if (!player_) {
            driver.idle(*this);
            continue;
        }
        events_.clear();
        std::optional<FrameTime> time = driver.nextFrame(frameNumber_, events_);
        if (!time) {
            reportWrites();
            driver.idle(*this);
            continue;
        }
        if (Status rendered = renderFrame(*time, events_); !rendered) return rendered.error();
        driver.present(*this);
    }
    return finishRound();
}

Result<SessionReport> SessionCore::run(SessionDriver& driver) {
    // A window waits (in its loop) for a shadertoy that does not compile yet; --watch (below) too.
    Result<SessionReport> round = player_ || live_ ? runRound(driver) : Result<SessionReport>(Error(problems_));
    if (!plan_.options.watch) {
        if (!round && !player_ && !problems_.empty()) return Error(problems_);
        return round;
    }
    // --watch: after every change, the run's frames again with what changed rebuilt.
    auto stop = [&] { return stopRequested(); };
    while (true) {
        if (!round && round.error().category() == Category::Interrupted) return round;
        observer_.roundFinished(round);
        std::optional<ShadertoyChange> change;
        while (!(change = watcher_->wait(stop))) {
            // Stopped while waiting: the last round's files are complete. Ctrl-C is how a --watch
            // run is ended (exit 0); SIGTERM still says the run was terminated.
            if (!stopRequested()) continue;
            if (watchdog_ && watchdog_->stop().reason == StopReason::Signal && watchdog_->stop().signal == SIGINT)
                return round ? round : Result<SessionReport>(report_);
            return Error("interrupted while watching the shadertoy's files; every round's files are complete",
                         Code::Interrupted);
        }
        startedAt_ = Clock::now();  // the next round's start-up: reloading and recompiling
        ReloadOutcome outcome = applyChange(std::move(change->files), std::move(change->plan));
        if (!player_ || (!outcome.applied && !outcome.problems.empty())) {
            Diagnostic nothing = notice("no frames written: the shadertoy as it is now does not run; the files of the "
                                        "last good round stay",
                                        Code::WatchChanged);
            observer_.notice(nothing);
            round = Error(outcome.problems.empty() ? problems_ : outcome.problems);
            continue;
        }
        if (plan_.end > plan_.first)
            observer_.notice(notice("rendering " + plural(plan_.end - plan_.first, "frame") + " again", Code::WatchChanged));
        player_->restart();
        driver.restart();
        round = runRound(driver);
    }
}

}  // namespace toyhost
