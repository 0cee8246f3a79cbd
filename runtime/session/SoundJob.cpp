#include "session/SoundJob.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "capture/SoundFile.h"
#include "capture/WavFile.h"
#include "core/Defaults.h"
#include "render/SoundRenderer.h"
#include "session/SettingChecks.h"

namespace toyhost {

namespace fs = std::filesystem;

Result<std::vector<float>> SoundJob::render(const PlayerPlan& shadertoy, double seconds) {
    if (seconds == 0) seconds = defaults::kSoundSeconds;  // the API's "0: the site's 180 s"
    if (Status length = checkSoundSecondsSetting(seconds); !length) return length.error();
    SoundRenderDesc desc;
    desc.seconds = seconds;
    desc.stopRequested = stopRequested_;
    if (shadertoy.soundSource) desc.source = &*shadertoy.soundSource;
    return renderSound(context_, shadertoy.manifest, shadertoy.images, desc);
}

Result<SessionReport> SoundJob::writeFile(const PlayerPlan& shadertoy, const SoundRequest& request, SessionReport report) {
    using Clock = std::chrono::steady_clock;
    const double seconds = request.seconds;  // checked by prepareSession
    const Clock::time_point started = Clock::now();
    Result<std::vector<float>> stereo = render(shadertoy, seconds);
    if (!stereo) return stereo.error();
    const Clock::time_point rendered = Clock::now();
    if (stopRequested_()) return Error("interrupted: no audio file was written", Code::Interrupted);
    auto samples = std::make_shared<std::vector<float>>(std::move(*stereo));
    const fs::path out = request.out;
    writer_.submit([out, samples]() -> Result<fs::path> {
        if (Status written = writeSoundFile(out, *samples); !written) return written.error();
        return out;
    });
    if (activity_) activity_->begin(RunActivity::Phase::WaitingForOutput);
    writer_.drain();
    if (activity_) activity_->idle();
    std::vector<Result<fs::path>> finished = writer_.takeFinished();
    if (stopRequested_()) {
        // A stop while the file was written ends the command as a stop during rendering does
        // (exit 128 + signal, no file), as `run` discards a video whose last frames were being
        // written: a file that was completed meanwhile is not kept either.
        for (Result<fs::path>& written : finished) {
            std::error_code ec;
            if (written && *written != "-" && fs::is_regular_file(*written, ec)) fs::remove(*written, ec);
        }
        return Error("interrupted while the audio file was being written: " + out.string() + " was not kept",
                     Code::Interrupted);
    }
    for (Result<fs::path>& written : finished) {
        if (!written) return written.error();
        if (*written == "-") report.toStdout = true;
        else report.files.push_back(*written);
    }
    report.firstFrameSeconds = std::chrono::duration<double>(rendered - started).count();
    report.restSeconds = std::chrono::duration<double>(Clock::now() - rendered).count();
    report.soundSeconds = seconds;
    return report;
}

Result<std::shared_ptr<TemporaryFiles>> SoundJob::soundTrack(SessionPlan& plan, SessionObserver& observer) {
    const SessionOptions& o = plan.options;
    if (!plan.shadertoy.manifest.sound) return std::shared_ptr<TemporaryFiles>();
    const bool video = plan.output && plan.output->kind().soundTrack;
    const double fps = o.settings.fps.value_or(defaults::kFps);
    const double end = std::min(o.settings.startTime + *o.frames / fps, defaults::kSoundSeconds);
    if (!video || *o.frames <= 0 || end <= o.settings.startTime) {
        Diagnostic skipped;
        skipped.severity = Severity::Notice;
        skipped.code = Code::SoundSkipped;
        skipped.message = video ? "the Sound pass ends at 180 s, before this run starts: the video has no sound"
                                : "the Sound pass is not rendered: only a video --out (" +
                                      extensionsWhere(&OutputKind::soundTrack) +
                                      ") carries sound; `toyhost sound` writes it to an audio file";
        skipped.pass = "Sound";
        observer.notice(skipped);
        return std::shared_ptr<TemporaryFiles>();
    }
    Result<std::vector<float>> stereo = render(plan.shadertoy, end);
    if (!stereo) return stereo.error();
    const std::size_t skip =
        std::min(stereo->size(), 2 * static_cast<std::size_t>(std::llround(o.settings.startTime * defaults::kSampleRate)));
    auto track = std::make_shared<TemporaryFiles>("soundtrack", std::initializer_list<const char*>{"wav"});
    if (!track->registerAll()) return Error("not started: toyhost is stopping", Code::Interrupted);
    auto samples = std::make_shared<std::vector<float>>(stereo->begin() + static_cast<std::ptrdiff_t>(skip), stereo->end());
    writer_.submit([track, samples]() -> Result<fs::path> {
        if (Status wav = writeWav16((*track)[0], *samples, static_cast<int>(defaults::kSampleRate)); !wav)
            return wav.error();
        return (*track)[0];
    });
    writer_.drain();
    for (Result<fs::path>& written : writer_.takeFinished())
        if (!written) return written.error();
    plan.options.video.audio = (*track)[0];
    return track;
}

}  // namespace toyhost
