#include "session/Recording.h"

#include <algorithm>

#include "core/ByteText.h"
#include "session/FiniteCheck.h"

namespace toyhost {

namespace fs = std::filesystem;

namespace {

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

Recording::Recording(std::unique_ptr<SessionPlan> plan, int firstFrame, RunActivity* activity,
                     std::function<bool()> stopRequested)
    : ownedPlan_(std::move(plan)), plan_(*ownedPlan_), first_(firstFrame), activity_(activity),
      stopRequested_(std::move(stopRequested)), pass_(plan_.options.capturePass) {}

Recording::~Recording() = default;

Result<std::unique_ptr<Recording>> Recording::ofNextFrames(SessionPlan plan, int firstFrame, RunActivity* activity,
                                                           std::function<bool()> stopRequested, const Player& player,
                                                           SessionObserver& observer) {
    std::unique_ptr<Recording> recording(new Recording(std::make_unique<SessionPlan>(std::move(plan)), firstFrame,
                                                       activity, std::move(stopRequested)));
    if (Status begun = recording->begin(player, observer); !begun) return begun.error();
    return recording;
}

Result<std::vector<fs::path>> Recording::end(double renderSeconds, SessionObserver& observer, FiniteCheck& finite) {
    Status completed = complete();
    if (!completed) {
        (void)abandon();
        return completed.error();
    }
    SessionReport done;
    report(done, renderSeconds, observer, finite);
    return std::move(done.files);
}

Status Recording::begin(const Player& player, SessionObserver& observer) {
    if (recorder_) return okStatus();
    Result<std::unique_ptr<FrameConsumer>> created =
        startFrameConsumer(plan_, player, activity_, stopRequested_, observer);
    if (!created) return created.error();
    recorder_ = std::move(*created);
    captured_.clear();
    return okStatus();
}

bool Recording::captures(int frame) const { return recorder_ && recorder_->captures(frame); }

Status Recording::rendered(const Player& player, int frame) {
    if (!recorder_) return okStatus();
    const bool captured = recorder_->captures(frame);
    if (Status recorded = recorder_->rendered(RenderedFrame{frame, player.output(pass_), player}); !recorded)
        return recorded;
    if (captured) captured_.push_back(frame);
    return okStatus();
}

Status Recording::complete() { return recorder_ ? recorder_->finish() : okStatus(); }

void Recording::report(SessionReport& report, double renderSeconds, SessionObserver& observer, FiniteCheck& finite) {
    if (!recorder_) return;
    const ConsumedFrames consumed = recorder_->consumed();
    report.bytesWritten = consumed.bytesWritten;
    report.encoderThreads = consumed.encoderThreads;
    report.videoEncoder = consumed.videoEncoder;
    report.captureTimes = consumed.times;
    report.captureTimes->render = renderSeconds;
    if (const auto& nonFinite = consumed.firstNonFinite)
        if (auto warning = finite.check(pass_, nonFinite->first, nonFinite->second, FiniteCheck::Coverage::CapturedFrames))
            observer.notice(*warning);
    const std::vector<int>& dropped = consumed.dropped;
    if (!dropped.empty())
        observer.notice(notice(plural(static_cast<int>(dropped.size()), "frame") +
                                   " were not recorded: the encoders were behind and real-time mode does not "
                                   "wait for them (use --fps for every frame)",
                               Code::CaptureDropped));
    const OutputKind& kind = plan_.output->kind();
    if (kind.oneFile()) report.files.push_back(plan_.output->pathFor(0));
    if (kind.filePerFrame())
        for (int frame : captured_)
            if (std::find(dropped.begin(), dropped.end(), frame) == dropped.end())
                report.files.push_back(plan_.output->pathFor(frame));
    recorder_.reset();  // complete; a next round has its own
}

std::string Recording::abandon() {
    if (!recorder_) return {};
    const FrameConsumer::Abandoned a = recorder_->abandon();
    const OutputKind& kind = plan_.output->kind();
    std::string message = kind.oneFile()  ? "; the unfinished " + std::string(kind.name) + " was discarded"
                          : !kind.toFile ? "; " + plural(a.written, "frame") + " went to stdout"
                                         : "; " + plural(a.written, "file") + " written";
    if (a.dropped > 0) message += ", " + plural(a.dropped, "captured frame") + " not written (dropped)";
    return message;
}

void Recording::discardVideo() {
    if (!plan_.output->kind().oneFile()) return;
    std::error_code ec;
    fs::remove(plan_.output->pathFor(0), ec);
}

}  // namespace toyhost
