#include "drivers/window/WindowDriver.h"

#include <atomic>

#include "core/Defaults.h"
#include "drivers/window/WindowContext.h"
#include "drivers/window/WindowEvents.h"
#include "gl/GlThread.h"
#include "render/Present.h"
#include "session/AllProblems.h"
#include "timing/FrameClock.h"
#include "timing/ProgressLine.h"
#include "timing/RealTimeClock.h"

namespace toyhost {

namespace {

double monotonicNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

class WindowDriver final : public SessionDriver {
public:
    WindowDriver(WindowContext& window, WindowEvents& events, const SessionOptions& o, SessionObserver& observer)
        : window_(window), events_(events), o_(o), observer_(observer), clock_(clockOptions(o), monotonicNow()),
          wallStart_(o.wallClock.value_or(localWallClockNow())) {}

    bool poll(SessionCore& s) override {
        if (events_.quitRequested()) return false;
        const double now = monotonicNow();
        if (events_.takeControl(Control::Help)) observer_.notice(notice(controlsHelp(), Code::WindowHelp));
        if (events_.takeControl(Control::Restart)) {
            s.restart();
            clock_.restart(now);  // while paused, the restarted frame is still shown
        }
        if (events_.takeControl(Control::Pause)) clock_.setPaused(!clock_.paused(), now);
        if (events_.takeControl(Control::Step)) clock_.stepOnce();
        if (events_.takeControl(Control::Screenshot))
            if (Status shot = s.screenshot(); !shot) observer_.notice(shot.error().first());
        // The canvas is the framebuffer (HiDPI: pixels, not window coordinates), except while
        // recording: a recording has one size, so the canvas stays at --size and is scaled to fit.
        framebuffer_ = events_.framebufferSize();
        if (s.running() && !o_.outPattern && framebuffer_.width > 0 && framebuffer_.height > 0)
            if (Status resized = s.resize(framebuffer_.width, framebuffer_.height); !resized)
                observer_.notice(resized.error().first());
        showTitle(s, now);
        return true;
    }

    std::optional<FrameTime> nextFrame(int, std::vector<InputEvent>& events) override {
        // Input while paused makes the site paint one frame at the paused time.
        if (clock_.paused() && events_.hasEvents()) clock_.forceFrame();
        if (!clock_.shouldRender()) return std::nullopt;
        events_.takeEvents(events);
        FrameTime time = clock_.frame(monotonicNow(), localWallClockNow());
        if (o_.fps || o_.wallClock) time.date = dateAt(wallStart_ + (time.time - o_.startTime));
        return time;
    }

    void present(SessionCore& s) override {
        events_.setCanvasSize(s.player().width(), s.player().height());
        presentToDefaultFramebuffer(s.player().output(PassId::Image), framebuffer_.width, framebuffer_.height);
        (void)window_.present();
    }

    void idle(SessionCore& s) override {
        // Paused, or waiting for a shadertoy that compiles: keep the window's content and wait.
        if (s.running() && s.player().frame() > 0) {
            present(s);
        } else {
            clearDefaultFramebuffer(framebuffer_.width, framebuffer_.height);
            (void)window_.present();
        }
        events_.waitForInput(0.05);
    }

private:
    static RealTimeClockOptions clockOptions(const SessionOptions& o) {
        return {o.fps, o.startTime, 1.0 / defaults::kRestartTimeDelta};
    }
    static Diagnostic notice(std::string message, Code code) {
        Diagnostic d;
        d.severity = Severity::Notice;
        d.code = code;
        d.message = std::move(message);
        return d;
    }
    void showTitle(SessionCore& s, double now) {
        // The state changes at once; the counters a few times a second.
        const bool paused = clock_.paused();
        if (paused == titlePaused_ && now - titleShownAt_ < 0.25) return;
        titlePaused_ = paused;
        titleShownAt_ = now;
        events_.setTitle(formatWindowTitle({s.name(), clock_.measuredFrameRate(), s.running() ? s.player().frame() - 1 : -1,
                                            clock_.time(), paused,
                                            s.problems().empty() ? "" : formatDiagnostic(s.problems().front())}));
    }

    WindowContext& window_;
    WindowEvents& events_;
    const SessionOptions& o_;
    SessionObserver& observer_;
    RealTimeClock clock_;
    double wallStart_;
    GlSurface::Size framebuffer_;
    bool titlePaused_ = false;
    double titleShownAt_ = -1;
};

}  // namespace

Result<SessionReport> runWindow(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog) {
    Result<SessionPlan> prepared = prepareSession(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    WindowOptions windowOptions;
    windowOptions.width = *prepared->options.width;
    windowOptions.height = *prepared->options.height;
    const std::string& name = prepared->shadertoy.manifest.name;
    windowOptions.title = name.empty() ? "toyhost" : name + " - toyhost";
    Result<std::shared_ptr<WindowContext>> window = WindowContext::create(windowOptions);
    if (!window) return window.error();
    (*window)->releaseCurrent();  // the GL thread makes it current

    std::atomic<bool> done{false};
    std::optional<Result<SessionReport>> result;
    WindowEvents events(**window, [&] {
        if (watchdog) watchdog->requestStop(StopReason::Quit);  // the grace period starts now
    });
    GlThread gl([&] {
        if (!prepared->options.outPattern) {  // the canvas is the framebuffer, in pixels
            const GlSurface::Size fb = events.framebufferSize();
            prepared->options.width = fb.width;
            prepared->options.height = fb.height;
        }
        {
            Result<std::unique_ptr<SessionCore>> session = SessionCore::start(std::move(*prepared), *window, observer, watchdog);
            if (session) {
                (void)(*window)->setSwapInterval(1);
                WindowDriver driver(**window, events, (*session)->plan().options, observer);
                result = (*session)->run(driver);
            } else {
                result = session.error();
            }
        }  // the SessionCore ends here, on the thread its context is current on
        (*window)->releaseCurrent();
        done = true;
        events.wake();
    });
    while (!done) events.pump(0.1);
    gl.join();
    return std::move(*result);
}

}  // namespace toyhost
