// SessionObserver: how a run talks to whoever started it (the CLI) while it runs: notices, progress,
// and the question "should I stop?". The library never prints; the CLI decides how to show these.
// No GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "core/RunActivity.h"
#include "timing/ProgressLine.h"

namespace toyhost {

// What a run did (for the one-line summary).
struct SessionReport {
    std::string manifestName;
    std::string context;                   // GL backend description
    int width = 0;
    int height = 0;
    int framesRendered = 0;
    std::vector<std::filesystem::path> files;
    double seconds = 0;                    // wall time of the frame loop, GPU and encoders included
    double firstFrameSeconds = 0;          // from start of run() to the first frame finished
    std::uint64_t bytesWritten = 0;        // by the capture (file sizes; the video's size)
    int encoderThreads = 0;                // encoder threads the capture used (0: synchronous)
};

class SessionObserver {
public:
    virtual ~SessionObserver() = default;
    virtual void notice(const Diagnostic& notice) = 0;
    // Called on the render thread after every frame; keep it cheap.
    virtual void progress(const RunProgress& progress) { (void)progress; }
    // Polled before every frame; true ends the run with an interrupted error (Code::Interrupted), cleanly (a video
    // being encoded is discarded, image files already written stay).
    virtual bool stopRequested() const { return false; }
    // --watch: a round of frames ended (`report`) or failed (`error`); the run now waits for the
    // next change of the shadertoy's files.
    virtual void roundFinished(const Result<SessionReport>& round) { (void)round; }
    // Where the run publishes what its render thread is doing, for a watchdog on another thread
    // (core/RunActivity.h); nullptr when nobody watches (then passes are not waited for one by one).
    virtual RunActivity* activity() { return nullptr; }
};

}  // namespace toyhost
