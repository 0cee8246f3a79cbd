// SoundJob: the Sound pass (mainSound) of a session, rendered on its GL context: the samples
// (`toyhost sound`, the library's renderSound), the audio file `toyhost sound` writes, and the sound
// track of a video --out (rendered up front from the run's start time and written as a temporary
// WAV that ffmpeg reads). Files are written on the session's BackgroundWriter, off the GL thread.
// Needs the GL context current on the calling thread.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "core/Result.h"
#include "core/RunActivity.h"
#include "core/TemporaryFiles.h"
#include "gl/GlContext.h"
#include "player/PlayerDesc.h"
#include "session/BackgroundWriter.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {

class SoundJob {
public:
    SoundJob(GlContext& context, BackgroundWriter& writer, RunActivity* activity, std::function<bool()> stopRequested)
        : context_(context), writer_(writer), activity_(activity), stopRequested_(std::move(stopRequested)) {}

    // Interleaved stereo samples at the site's rate, `seconds` long (0: the site's 180 s).
    Result<std::vector<float>> render(const PlayerPlan& shadertoy, double seconds);
    // `toyhost sound`: the request's audio file; the report says what was written and how long.
    Result<SessionReport> writeFile(const PlayerPlan& shadertoy, const SoundRequest& request, SessionReport report);
    // A video --out of a shadertoy with a Sound pass: its sound track as a temporary WAV (set as
    // the video's audio in `plan`); nothing, with a notice, when the output carries no sound.
    Result<std::shared_ptr<TemporaryFiles>> soundTrack(SessionPlan& plan, SessionObserver& observer);

private:
    GlContext& context_;
    BackgroundWriter& writer_;
    RunActivity* activity_;
    std::function<bool()> stopRequested_;
};

}  // namespace toyhost
