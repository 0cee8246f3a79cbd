#include "session/FrameConsumer.h"

#include "session/FrameRecorder.h"

namespace toyhost {

Result<std::unique_ptr<FrameConsumer>> startFrameConsumer(const SessionPlan& plan, const Player& player,
                                                          RunActivity* activity, std::function<bool()> stopRequested,
                                                          SessionObserver& observer) {
    Result<std::unique_ptr<FrameRecorder>> recorder =
        FrameRecorder::create(recorderSettings(plan, activity, std::move(stopRequested)), player);
    if (!recorder) return recorder.error();
    if (!(*recorder)->videoEncoderChoice().empty()) {
        Diagnostic choice;
        choice.severity = Severity::Notice;
        choice.code = Code::CaptureFfmpeg;
        choice.message = (*recorder)->videoEncoderChoice();
        observer.notice(choice);
    }
    return std::unique_ptr<FrameConsumer>(std::move(*recorder));
}

}  // namespace toyhost
