// Recording: what a run writes with --out, round by round: the FrameConsumer of the round (the CPU
// readback adapter: readback, encoders, sink), which frames it captures (the capture-every rule),
// the files it completed,
// and the rules for a run that does not complete (complete image files stay, a video or a raw
// stream being written is discarded, dropped frames are counted). The session's loop asks it
// whether a frame is captured and hands it the frames; the report's output facts come from here.
// Needs the player's GL context current for its whole life.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/Result.h"
#include "player/Player.h"
#include "session/FrameConsumer.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {

class FiniteCheck;

class Recording {
public:
    // A recording of `plan`'s output (plan.output must be set).
    // `stopRequested`: asked while the render thread waits for the consumer (the encoders).
    Recording(const SessionPlan& plan, RunActivity* activity, std::function<bool()> stopRequested = {});
    ~Recording();
    // A recording of the next frames of a session that records nothing (the library's
    // Session::record), begun: it owns `plan` (planRecording's: output, frames, capture-every,
    // pass) and numbers the run's frames from `firstFrame`, as a run's files are numbered from 0.
    static Result<std::unique_ptr<Recording>> ofNextFrames(SessionPlan plan, int firstFrame, RunActivity* activity,
                                                           std::function<bool()> stopRequested, const Player& player,
                                                           SessionObserver& observer);
    // The recording's own number of the run's frame `frame` (0 from the frame it began at).
    int captureFrame(int frame) const { return frame - first_; }
    // ofNextFrames' end: completes it and gives the files written, or leaves nothing unfinished
    // (an unfinished video removed) and gives the error.
    Result<std::vector<std::filesystem::path>> end(double renderSeconds, SessionObserver& observer, FiniteCheck& finite);

    // Starts a round's consumer for `player`'s canvas (a video's ffmpeg command line); a notice
    // says which video encoder --codec auto chose. A round already begun is kept.
    Status begin(const Player& player, SessionObserver& observer);
    bool begun() const { return recorder_ != nullptr; }
    // Whether frame `frame` of the run is captured (the capture-every rule and the last frame).
    bool captures(int frame) const;
    // Whether the Image pass must be drawn on frame `frame` for this recording.
    bool needsImage(int frame) const { return captures(frame) && pass_ == PassId::Image; }
    // After every rendered frame: captures it if it is captured, hands the reads that completed
    // to the encoders (capture/FrameStream.h).
    Status rendered(const Player& player, int frame);
    std::uint64_t bytesWritten() const { return recorder_ ? recorder_->bytesWritten() : 0; }

    // Waits for every readback and encoder and completes the round's output.
    Status complete();
    // After complete(): the report's output facts (files, bytes, encoders, capture times with the
    // loop's `renderSeconds`); warnings (a NaN in a float capture, frames dropped in real time) go
    // to `observer`, `finite` checks the captured float frames. The next round begins anew.
    void report(SessionReport& report, double renderSeconds, SessionObserver& observer, FiniteCheck& finite);
    // A run that ends interrupted: what it leaves, as the end of the message ("; 3 files written").
    std::string abandon();
    // An interrupted run's video is discarded even when finish() just completed it.
    void discardVideo();

private:
    Recording(std::unique_ptr<SessionPlan> plan, int firstFrame, RunActivity* activity, std::function<bool()> stopRequested);
    std::unique_ptr<SessionPlan> ownedPlan_;  // ofNextFrames' plan (plan_ refers to it)
    const SessionPlan& plan_;
    int first_ = 0;
    RunActivity* activity_;
    std::function<bool()> stopRequested_;
    PassId pass_;
    std::unique_ptr<FrameConsumer> recorder_;
    std::vector<int> captured_;  // frame numbers captured this round
};

}  // namespace toyhost
