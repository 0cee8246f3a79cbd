#include "session/HostedSession.h"

#include "gl/CurrentContext.h"
#include "gl/HeadlessContext.h"
#include "image/PixelConversion.h"
#include "session/SettingChecks.h"
#include "session/WatchdogSetup.h"

namespace toyhost {

Status HostedSession::start(SessionOptions options, Context context) {
    const std::string file = options.target.string();
    Result<SessionPlan> plan = prepareSession(options);
    if (!plan) return plan.error();
    media_ = plan->media;
    defines_ = plan->defines;
    timeline_.emplace(timelineOf(*plan));
    watchdog_ = makeWatchdog(plan->options, libraryExpiryHooks(file));
    if (context == Context::Headless) {
        // The environment chooses the EGL platform, as for every toyhost command.
        Result<EglPlatform> platform = eglPlatformFromEnvironment();
        if (!platform) return platform.error();
        plan->options.eglPlatform = *platform;
        HeadlessOptions headlessOptions;
        headlessOptions.platform = plan->options.eglPlatform;
        Result<std::shared_ptr<GlContext>> made = createHeadlessContext(headlessOptions);
        if (!made) return made.error();
        context_ = *made;
        ownContext_ = true;
    } else {
        Result<std::shared_ptr<GlContext>> adopted = adoptCurrentContext();
        if (!adopted) return adopted.error();
        context_ = *adopted;
    }
    Result<std::unique_ptr<SessionCore>> core =
        withGl([&] { return SessionCore::start(std::move(*plan), context_, notices_, watchdog_.get()); });
    if (!core) return core.error();
    core_ = std::move(*core);
    return okStatus();
}

HostedSession::~HostedSession() {
    if (!core_) return;
    withGl([&] {
        core_.reset();
        return 0;
    });
}

Status HostedSession::usable(std::string_view call) const {
    if (std::this_thread::get_id() != thread_)
        return Error("a session is used on the thread that created it: " + std::string(call) +
                         "() was called from another thread (hand the call to the session's thread, or create "
                         "the session on the thread that uses it)",
                     Code::Usage);
    return current();
}

Status HostedSession::expired() const {
    if (watchdog_)
        if (std::optional<Diagnostic> d = watchdog_->expired()) return Error(*d);
    return okStatus();
}

Status HostedSession::draw(const FrameTime& time, std::span<const InputEvent> events) {
    Status drawn = core_->renderFrame(time, events);
    // Submitted now, so that the GPU works on the frame while the caller goes on: a read that
    // follows waits less (llvmpipe would start the frame only when it is read: step(); frame()
    // on a trivial shader from Python, 1.18x the CLI's frame without this, 0.94-1.02x with it).
    core_->submit();
    return drawn;
}

Status HostedSession::next(std::span<const InputEvent> given) {
    events_.clear();
    const FrameTime time = timeline_->next(core_->frame(), events_);
    events_.insert(events_.end(), given.begin(), given.end());
    return draw(time, events_);
}

Status HostedSession::nextAt(double time, double timeDelta, double frameRate, std::span<const InputEvent> given) {
    events_.clear();
    timeline_->eventsBefore(core_->frame(), events_);
    events_.insert(events_.end(), given.begin(), given.end());
    return draw(timeline_->atTime(time, timeDelta, frameRate), events_);
}

namespace {
// The pass read into `scratch` (Renderer::readRgba8 / readRgba32f), then its rows into `out`.
template <class T>
void readInto(const SessionCore& core, PassId pass, std::vector<T>& scratch, std::span<T> out, bool topFirst) {
    if constexpr (std::is_same_v<T, float>) core.readRgba32f(pass, scratch);
    else core.readRgba8(pass, scratch);
    convertRgbaRows(scratch.data(), out, core.width(), core.height(), topFirst);
}
}  // namespace

void HostedSession::readPass(PassId pass, std::span<std::uint8_t> out, bool topFirst) const {
    withGl([&] {
        readInto(*core_, pass, bytes_, out, topFirst);
        return 0;
    });
}

void HostedSession::readPass(PassId pass, std::span<float> out, bool topFirst) const {
    withGl([&] {
        readInto(*core_, pass, floats_, out, topFirst);
        return 0;
    });
}

Status HostedSession::checkEvents(std::span<const InputEvent> events) {
    using T = InputEvent::Type;
    for (const InputEvent& e : events)
        if (Status ok = checkInputEventSetting(e.type == T::MouseDown || e.type == T::MouseMove, e.x, e.y,
                                               e.type == T::KeyDown || e.type == T::KeyUp, e.key);
            !ok)
            return ok;
    return okStatus();
}

}  // namespace toyhost
