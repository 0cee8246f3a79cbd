#include "drivers/headless/HeadlessRun.h"

#include <cmath>
#include <span>

#include "capture/WavFile.h"
#include "core/Defaults.h"
#include "core/TemporaryFiles.h"
#include "render/SoundRenderer.h"

#include <chrono>
#include <memory>

#include "input/InputScriptPlayer.h"
#include "player/Player.h"
#include "timing/FrameClock.h"
#include "session/FiniteCheck.h"
#include "session/AllProblems.h"
#include "session/FrameRecorder.h"
#include "session/ShadertoyWatcher.h"

namespace toyhost {

std::vector<std::filesystem::path> capturedFiles(const OutputPattern& output, int first, int end, int frames,
                                                 int captureEvery) {
    std::vector<std::filesystem::path> files;
    if (output.format() == OutputFormat::RawStream) return files;
    for (int frame = first; frame < end; ++frame) {
        if (!isCapturedFrame(frame, frames, captureEvery)) continue;
        files.push_back(output.pathFor(frame));
        if (output.streamed()) break;
    }
    return files;
}

namespace {

// The error of a run stopped by a signal before frame `frame` of `frames`: what was written and
// what was not (queued frames are dropped).
Error interrupted(int frame, int frames, FrameRecorder* recorder, const PreparedRun& run) {
    std::string message = frame < frames
                              ? "interrupted after " + std::to_string(frame) + " of " + std::to_string(frames) + " frames"
                              : "interrupted while the last captured frames were written";
    if (recorder) {
        const FrameRecorder::Abandoned a = recorder->abandon();
        const auto plural = [](int n, const char* what) {
            return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
        };
        switch (run.output->format()) {
            case OutputFormat::Video: message += "; the unfinished video was discarded"; break;
            case OutputFormat::RawStream: message += "; " + plural(a.written, "frame") + " went to stdout"; break;
            default: message += "; " + plural(a.written, "file") + " written"; break;
        }
        if (a.dropped > 0) message += ", " + plural(a.dropped, "captured frame") + " not written (dropped)";
    }
    return Error(message, Code::Interrupted);
}

// Renders frames 0..frames-1 of `player` (from iFrame 0) with the fixed clock, the input scripts
// and, when `run` has an output, a new FrameRecorder; fills `report`.
Status renderFrames(Player& player, const PreparedRun& run, RunObserver& observer, RunReport& report,
                    std::chrono::steady_clock::time_point started) {
    using Clock = std::chrono::steady_clock;
    const RunOptions& o = run.options;
    std::unique_ptr<FrameRecorder> recorder;
    if (run.output) {
        Result<std::unique_ptr<FrameRecorder>> created = FrameRecorder::create(recorderSettings(run, observer.activity()), player);
        if (!created) return created.error();
        recorder = std::move(*created);
    }

    report.manifestName = player.manifest().name;
    report.context = player.context().describe();
    report.width = player.width();
    report.height = player.height();
    report.framesRendered = 0;

    const double wallClock = o.wallClock ? *o.wallClock : localWallClockNow();
    const FrameClock clock(*o.fps, o.startTime, wallClock);
    MouseScriptPlayer mouseScript(run.mouse);
    KeyScriptPlayer keyScript(run.keys);
    std::vector<InputEvent> events;
    events.reserve(64);

    // --resume: the player continues from the checkpoint; the scripts are replayed up to it
    // (their events are already in the saved mouse and keyboard state).
    int start = 0;
    if (run.resume) {
        if (Status restored = player.restoreState(run.resume->state); !restored)
            return inFile(o.resume->string(), restored.error());
        start = run.resume->state.frame;
        for (int frame = 0; frame < start; ++frame) {
            events.clear();
            mouseScript.eventsBeforeFrame(frame, clock.time(frame), events);
            keyScript.eventsBeforeFrame(frame, clock.time(frame), events);
        }
    }
    auto saveCheckpoint = [&]() -> Status {
        if (!o.checkpoint) return okStatus();
        Checkpoint c{player.saveState(), *o.fps, o.startTime, wallClock, player.manifest().name,
                     codeHash(player.manifest()), channelMedia(player.manifest())};
        return writeCheckpoint(*o.checkpoint, c);
    };
    bool hasBuffers = false;
    for (const PassDesc& pass : player.manifest().passes) hasBuffers = hasBuffers || isBuffer(pass.id);
    FiniteCheck finite;
    using Coverage = FiniteCheck::Coverage;
    std::vector<float> bufferPixels;
    // Every buffer once: after every frame with --check-finite, else after the last one.
    auto checkBuffers = [&](int frame) {
        for (const PassDesc& pass : player.manifest().passes) {
            if (!isBuffer(pass.id) || finite.reported(pass.id)) continue;
            player.readRgba32f(pass.id, bufferPixels);
            const Coverage coverage = o.checkFinite ? Coverage::EveryFrame : Coverage::LastFrameOnly;
            if (auto warning = finite.check(pass.id, frame, bufferPixels, player.width(), coverage))
                observer.notice(*warning);
        }
    };
    RunProgress progress;
    progress.frames = run.end - run.first;

    const auto loopStart = Clock::now();
    for (int frame = start; frame < run.end; ++frame) {
        if (observer.stopRequested()) {
            (void)saveCheckpoint();  // best effort: the run is ending anyway
            return interrupted(frame, run.end, recorder.get(), run);
        }
        const double time = clock.time(frame);
        events.clear();
        mouseScript.eventsBeforeFrame(frame, time, events);
        keyScript.eventsBeforeFrame(frame, time, events);
        if (frame < run.first) {
            // Before the frame range: buffers must still run (their state carries over); a
            // shadertoy without buffers only needs its inputs and counters to advance.
            if (hasBuffers) player.step(clock.frameTime(frame), events, /*renderImage=*/false);
            else player.skipFrame(events);
            if (o.checkpointEvery && (frame + 1) % *o.checkpointEvery == 0)
                if (Status saved = saveCheckpoint(); !saved) return saved;
            continue;
        }
        const bool captured = run.output && isCapturedFrame(frame, *o.frames, *o.captureEvery);
        // Nothing reads the Image pass, so a run that captures renders it only on the frames it
        // captures: long simulations captured every K frames run at buffer speed. A run without
        // --out renders every pass of every frame (a dry run, and the render-only benchmark).
        const bool renderImage = !run.output || (captured && o.capturePass == PassId::Image);
        player.step(clock.frameTime(frame), events, renderImage);

        // Readbacks may wait for the GPU: the watchdog is told which pass it is still drawing.
        player.publishPendingDraws();
        if (captured) {
            if (Status saved = recorder->capture(player, frame); !saved) return saved;
        } else if (recorder) {
            if (Status polled = recorder->poll(); !polled) return polled;
        }
        player.publishPendingDraws();
        if (o.checkFinite) checkBuffers(frame);
        // Frame 0 waits for the GPU once so that the time to the first frame is real.
        if (o.finishEachFrame || frame == run.first) player.finish();
        if (frame == run.first) report.firstFrameSeconds = std::chrono::duration<double>(Clock::now() - started).count();
        if (o.checkpointEvery && (frame + 1) % *o.checkpointEvery == 0)
            if (Status saved = saveCheckpoint(); !saved) return saved;
        report.framesRendered = frame + 1 - run.first;
        progress.framesDone = frame + 1 - run.first;
        progress.seconds = std::chrono::duration<double>(Clock::now() - loopStart).count();
        progress.bytesWritten = recorder ? recorder->bytesWritten() : 0;
        observer.progress(progress);
    }
    if (recorder) {
        player.publishPendingDraws();
        Status finished = recorder->finish();
        // A signal during the final writes still ends the run as interrupted (exit 130/143),
        // whatever the encoders managed; an interrupted video is discarded even if it was just
        // completed, as every interrupted video is.
        if (observer.stopRequested()) {
            if (finished && run.output->format() == OutputFormat::Video) {
                std::error_code ec;
                std::filesystem::remove(run.output->pathFor(0), ec);
            }
            return interrupted(run.end, run.end, recorder.get(), run);
        }
        if (!finished) return finished;
        report.bytesWritten = recorder->bytesWritten();
        report.encoderThreads = recorder->encoderThreads();
        if (const auto& nonFinite = recorder->firstNonFinite())
            if (auto warning = finite.check(o.capturePass, nonFinite->first, nonFinite->second, Coverage::CapturedFrames))
                observer.notice(*warning);
    }
    if (!o.checkFinite && run.end > 0) checkBuffers(run.end - 1);
    if (Status saved = saveCheckpoint(); !saved) return saved;
    player.finish();  // the reported time includes the GPU's work
    report.seconds = std::chrono::duration<double>(Clock::now() - loopStart).count();
    report.files = run.output ? capturedFiles(*run.output, run.first, run.end, *o.frames, *o.captureEvery)
                              : std::vector<std::filesystem::path>{};
    return okStatus();
}

}  // namespace

Result<RunReport> runHeadless(const RunOptions& options, RunObserver& observer) {
    const auto started = std::chrono::steady_clock::now();
    Result<PreparedRun> prepared = prepareRun(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    PreparedRun& run = *prepared;
    const RunOptions& o = run.options;
    for (const Diagnostic& line : run.plan.notices) observer.notice(line);

    HeadlessOptions headless;
    headless.platform = o.eglPlatform;
    Result<std::shared_ptr<GlContext>> context = createHeadlessContext(headless);
    if (!context) return context.error();

    // The Sound pass: rendered up front into the video's sound track, from the run's start time;
    // other outputs carry no sound (`toyhost sound` writes it to an audio file).
    std::optional<TemporaryFiles> soundTrack;
    if (run.plan.manifest.sound) {
        const double fps = o.fps.value_or(defaults::kFps);
        const bool video = run.output && run.output->format() == OutputFormat::Video;
        const double end = std::min(o.startTime + *o.frames / fps, defaults::kSoundSeconds);
        if (video && *o.frames > 0 && end > o.startTime) {
            SoundRenderDesc sound;
            sound.seconds = end;
            sound.activity = observer.activity();
            sound.stopRequested = [&] { return observer.stopRequested(); };
            Result<std::vector<float>> stereo = renderSound(**context, run.plan.manifest, run.plan.images, sound);
            if (!stereo) return stereo.error();
            const std::size_t skip =
                std::min(stereo->size(), 2 * static_cast<std::size_t>(std::llround(o.startTime * defaults::kSampleRate)));
            soundTrack.emplace("soundtrack", std::initializer_list<const char*>{"wav"});
            if (!soundTrack->registerAll()) return Error("not started: toyhost is stopping", Code::Interrupted);
            if (Status wav = writeWav16((*soundTrack)[0], std::span<const float>(*stereo).subspan(skip),
                                        static_cast<int>(defaults::kSampleRate));
                !wav)
                return wav.error();
            run.options.video.audio = (*soundTrack)[0];
        } else {
            Diagnostic notice;
            notice.severity = Severity::Notice;
            notice.code = Code::SoundSkipped;
            notice.pass = "Sound";
            notice.message = video ? "the Sound pass ends at 180 s, before this run starts: the video has no sound"
                                   : "the Sound pass is not rendered: only a video --out (.mp4, .webm, .mov, .mkv) "
                                     "carries sound; `toyhost sound` writes it to an audio file";
            observer.notice(notice);
        }
    }

    PlayerDesc desc;
    desc.width = *o.width;
    desc.height = *o.height;
    desc.floatImage = run.output && run.output->format() == OutputFormat::Exr && o.capturePass == PassId::Image;
    desc.activity = observer.activity();
    desc.watchDraws = *o.frameTimeout > 0;
    std::optional<ShadertoyWatcher> watcher;
    if (o.watch) watcher.emplace(o.target, o.media, run.plan.manifest);
    auto stop = [&] { return observer.stopRequested(); };

    // With --watch, a shadertoy that does not compile yet waits for the fix.
    Result<std::unique_ptr<Player>> made = Player::create(*context, std::move(run.plan), desc);
    while (!made && watcher) {
        observer.roundFinished(made.error());
        std::optional<Result<PlayerPlan>> next = watcher->wait(stop);
        if (!next) return made.error();
        if (!*next) {
            made = next->error();
            continue;
        }
        run.plan = std::move(**next);
        made = Player::create(*context, std::move(run.plan), desc);
    }
    if (!made) return made.error();
    Player& player = **made;
    for (const Diagnostic& notice : player.compileNotices()) observer.notice(notice);

    RunReport report;
    Status round = renderFrames(player, run, observer, report, started);
    if (!watcher) {
        if (!round) return round.error();
        return report;
    }
    // --watch: after every change, the same frames again with what changed rebuilt (a pass that
    // does not compile keeps its last good program, and the run says so).
    while (true) {
        if (round) observer.roundFinished(report);
        else observer.roundFinished(round.error());
        if (!round && round.error().first().code == Code::Interrupted) return round.error();
        std::optional<Result<PlayerPlan>> next = watcher->wait(stop);
        if (!next) return report;  // stopped while waiting: the last round's files are complete
        if (!*next) {
            round = next->error();
            continue;
        }
        ReloadReport reloaded = player.reload(std::move(**next));
        if (!reloaded.problems.empty()) {
            round = Error(reloaded.problems);
            if (!reloaded.applied) continue;
            for (const Diagnostic& problem : reloaded.problems) observer.notice(problem);
        }
        player.restart();
        round = renderFrames(player, run, observer, report, std::chrono::steady_clock::now());
    }
}

}  // namespace toyhost
