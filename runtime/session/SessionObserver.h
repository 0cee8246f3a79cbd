// SessionObserver and SessionReport: how a session talks to whoever runs it (the CLI, a program
// that embeds toyhost) while it runs, and what it did. The library never prints; the observer
// decides how to show notices and progress, and summaryLines() is the one text form of a report
// every command prints. No GL needed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "timing/ProgressLine.h"

namespace toyhost {

// Where a capturing run's time went, in seconds. On the render thread: the player's frame calls
// (GPU waits included), reading frames back, and waiting for the encoders (back-pressure: the
// encoders are the bottleneck when this is large). On the encoder threads, summed over them:
// encoding (compression, conversion) and writing (files, or ffmpeg's pipe, which waits while
// ffmpeg encodes).
struct CaptureTimes {
    double render = 0;
    double readback = 0;
    double waitingForEncoders = 0;
    double encode = 0;
    double write = 0;
};

// What a run (or one round of a --watch run) did.
struct SessionReport {
    std::string name;        // the shadertoy's
    std::string context;     // the GL backend, one line
    std::string mode;        // "headless", "in a window"
    int width = 0;
    int height = 0;
    int frames = 0;          // frames rendered (not those simulated before a --frame-range)
    int samplesPerFrame = 1; // draws of Image averaged into each frame (--supersample, --motion-blur)
    // From the start of the command to the start of the first frame (loading, decoding images,
    // the GL context, compiling), the first frame itself (GPU work included), and every later
    // frame until every output was written.
    double startupSeconds = 0;
    double firstFrameSeconds = 0;
    double restSeconds = 0;   // the frames after the first, paused time left out
    double pausedSeconds = 0; // a window's pauses after the first frame
    std::vector<std::filesystem::path> files;  // complete output files (frames, a video, audio)
    std::optional<std::filesystem::path> checkpoint;
    std::uint64_t bytesWritten = 0;  // the captured frames' files (a video's size)
    int encoderThreads = 0;
    std::optional<CaptureTimes> captureTimes;  // runs that captured frames
    std::string videoEncoder;                  // the ffmpeg encoder a video used
    bool interactive = false;  // a window: no output is the normal case
    bool toStdout = false;     // raw frames went to stdout
    bool outputAsked = false;  // --out was given
    double soundSeconds = 0;   // `toyhost sound`: the length of the audio written

    // A next round's report: the session's facts (mode, context, samples, what was asked), no results.
    SessionReport nextRound() const {
        SessionReport fresh;
        fresh.mode = mode;
        fresh.context = context;
        fresh.interactive = interactive;
        fresh.outputAsked = outputAsked;
        fresh.toStdout = toStdout;
        fresh.samplesPerFrame = samplesPerFrame;
        return fresh;
    }
};

// The summary a command prints after a run, one line each ("ocean: 60 frames at 1280x720 ...",
// "wrote ..."), without the "toyhost: " prefix.
std::vector<std::string> summaryLines(const SessionReport& report);
// A --watch round after the first in one line: "2 frames in 7.7 ms; wrote 2 files (2.5 KiB):
// out_0.png .. out_1.png" (the first round's summary said the rest, which does not change).
std::string watchRoundLine(const SessionReport& report);

class SessionObserver {
public:
    virtual ~SessionObserver() = default;
    // Notices, warnings and problems that do not end the run (a reload that failed, a stand-in).
    virtual void notice(const Diagnostic& notice) = 0;
    // Problems that do not end the run, as one list (a reload whose passes do not compile): by
    // default each as a notice, at most 100, then one saying how many more.
    virtual void problems(const std::vector<Diagnostic>& list) {
        const std::size_t shown = list.size() > 100 ? 100 : list.size();
        for (std::size_t i = 0; i < shown; ++i) notice(list[i]);
        if (shown < list.size()) {
            Diagnostic more;
            more.severity = Severity::Notice;
            more.message = "... and " + std::to_string(list.size() - shown) + " more";
            notice(more);
        }
    }
    // After every frame, on the render thread; keep it cheap.
    virtual void progress(const RunProgress& progress) { (void)progress; }
    // A round of a --watch run ended (its report) or failed (its error); the run now waits for the
    // next change of the shadertoy's files.
    virtual void roundFinished(const Result<SessionReport>& round) { (void)round; }
};

}  // namespace toyhost
