#include "session/Recording.h"

#include <algorithm>

#include "session/FiniteCheck.h"

namespace toyhost {

namespace fs = std::filesystem;

namespace {

std::string plural(int n, const char* what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

Diagnostic notice(std::string message, Code code) {
    Diagnostic d;
    d.severity = Severity::Notice;
    d.code = code;
    d.message = std::move(message);
    return d;
}

}  // namespace

Recording::Recording(const SessionPlan& plan, RunActivity* activity, std::function<bool()> stopRequested)
    : plan_(plan), activity_(activity), stopRequested_(std::move(stopRequested)), pass_(plan.options.capturePass) {}

Recording::~Recording() = default;

Status Recording::begin(const Player& player, SessionObserver& observer) {
    if (recorder_) return okStatus();
    Result<std::unique_ptr<FrameRecorder>> created = FrameRecorder::create(
        recorderSettings(plan_, activity_, stopRequested_), player);
    if (!created) return created.error();
    recorder_ = std::move(*created);
    captured_.clear();
    if (!recorder_->videoEncoderChoice().empty())
        observer.notice(notice(recorder_->videoEncoderChoice(), Code::CaptureFfmpeg));
    return okStatus();
}

bool Recording::captures(int frame) const { return recorder_ && recorder_->captures(frame); }

Status Recording::rendered(const Player& player, int frame) {
    if (!recorder_) return okStatus();
    const bool captured = recorder_->captures(frame);
    if (Status recorded = recorder_->rendered(player, frame); !recorded) return recorded;
    if (captured) captured_.push_back(frame);
    return okStatus();
}

Status Recording::complete() { return recorder_ ? recorder_->finish() : okStatus(); }

void Recording::report(SessionReport& report, double renderSeconds, SessionObserver& observer, FiniteCheck& finite) {
    if (!recorder_) return;
    report.bytesWritten = recorder_->bytesWritten();
    report.encoderThreads = recorder_->encoderThreads();
    report.videoEncoder = recorder_->videoEncoder();
    report.captureTimes = CaptureTimes{renderSeconds, recorder_->readbackSeconds(), recorder_->waitSeconds(),
                                       recorder_->encodeSeconds(), recorder_->writeSeconds()};
    if (const auto& nonFinite = recorder_->firstNonFinite())
        if (auto warning = finite.check(pass_, nonFinite->first, nonFinite->second, FiniteCheck::Coverage::CapturedFrames))
            observer.notice(*warning);
    const std::vector<int>& dropped = recorder_->droppedFrames();
    if (!dropped.empty())
        observer.notice(notice(plural(static_cast<int>(dropped.size()), "frame") +
                                   " were not recorded: the encoders were behind and real-time mode does not "
                                   "wait for them (use --fps for every frame)",
                               Code::CaptureDropped));
    switch (plan_.output->format()) {
        case OutputFormat::Video: report.files.push_back(plan_.output->pathFor(0)); break;
        case OutputFormat::RawStream: break;
        default:
            for (int frame : captured_)
                if (std::find(dropped.begin(), dropped.end(), frame) == dropped.end())
                    report.files.push_back(plan_.output->pathFor(frame));
    }
    recorder_.reset();  // complete; a next round has its own
}

std::string Recording::abandon() {
    if (!recorder_) return {};
    const FrameRecorder::Abandoned a = recorder_->abandon();
    std::string message;
    switch (plan_.output->format()) {
        case OutputFormat::Video: message = "; the unfinished video was discarded"; break;
        case OutputFormat::RawStream: message = "; " + plural(a.written, "frame") + " went to stdout"; break;
        default: message = "; " + plural(a.written, "file") + " written"; break;
    }
    if (a.dropped > 0) message += ", " + plural(a.dropped, "captured frame") + " not written (dropped)";
    return message;
}

void Recording::discardVideo() {
    if (plan_.output->format() != OutputFormat::Video) return;
    std::error_code ec;
    fs::remove(plan_.output->pathFor(0), ec);
}

}  // namespace toyhost
