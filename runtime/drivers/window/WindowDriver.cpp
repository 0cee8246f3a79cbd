#include "drivers/window/WindowDriver.h"

#include <atomic>
#include <ctime>

#include "core/Defaults.h"
#include "drivers/window/Overlay.h"
#include "drivers/window/WindowContext.h"
#include "drivers/window/WindowEvents.h"
#include "gl/GlThread.h"
#include "image/ImageWriters.h"
#include "render/Present.h"
#include "session/BackgroundWriter.h"
#include "session/ShadertoyWatcher.h"
#include "session/CompileProblems.h"
#include "timing/FrameClock.h"
#include "timing/FramePacer.h"
#include "timing/RealTimeClock.h"
#include "timing/WindowTitle.h"

namespace toyhost {

namespace fs = std::filesystem;

namespace {

std::string fileSafe(std::string name) {
    for (char& c : name)
        if (c == '/' || c == '\\' || c == ':' || static_cast<unsigned char>(c) < 32) c = '_';
    return name.empty() ? std::string("toyhost") : name;
}

class WindowDriver final : public SessionDriver {
public:
    WindowDriver(WindowContext& window, WindowEvents& events, const SessionPlan& plan, ShadertoyWatcher& watcher,
                 SessionObserver& observer)
        : window_(window), events_(events), plan_(plan), o_(plan.options), watcher_(watcher), observer_(observer),
          clock_(clockOptions(plan), monotonicNow()) {}

    bool poll(SessionCore& s) override {
        reportScreenshots();
        if (events_.quitRequested()) return false;
        // Hot reload between frames: the watcher loaded and planned the files off this thread.
        if (std::optional<ShadertoyChange> change = watcher_.take()) {
            const ReloadOutcome outcome = s.reload(std::move(change->files), std::move(change->plan));
            // The site's compile paints a frame even while paused; here the shown frame is painted
            // again with the new code at the paused time, iFrame unchanged (docs/window.md). With
            // no frame shown yet (the first code that compiles), frame 0 is painted, as the site's
            // first good compile starts its render loop.
            if (outcome.applied && clock_.paused() && s.running()) {
                if (s.frame() > 0) (void)s.repaint(clock_.repaint(monotonicNow(), localWallClockNow()));
                else clock_.forceFrame();
            }
        }
        const double now = monotonicNow();
        if (events_.takeControl(Control::Help)) observer_.notice(notice(controlsHelp(), Code::WindowHelp));
        if (events_.takeControl(Control::Inspector)) toggleInspector();
        if (events_.takeControl(Control::Restart)) {
            s.restart();
            clock_.restart(now);  // while paused, the restarted frame is still shown
            if (pacer_) pacer_->reset();
        }
        if (events_.takeControl(Control::Pause)) {
            clock_.setPaused(!clock_.paused(), now);
            shownRate_.setPaused(clock_.paused(), now);
            if (pacer_) pacer_->reset();
        }
        if (events_.takeControl(Control::Step)) clock_.stepOnce();
        if (events_.takeControl(Control::Screenshot))
            if (Status shot = screenshot(s); !shot) observer_.notice(shot.error().first());
        // The canvas is the framebuffer (HiDPI: pixels, not window coordinates), except while
        // recording: a recording has one size, so the canvas stays at --size and is scaled to fit.
        framebuffer_ = events_.framebufferSize();
        if (s.running() && !o_.outPattern && framebuffer_.width > 0 && framebuffer_.height > 0)
            if (Status resized = s.resize(framebuffer_.width, framebuffer_.height); !resized)
                observer_.notice(resized.error().first());
        showTitle(s, now);
        return true;
    }

    bool paused() const override { return clock_.paused(); }

    std::optional<FrameTime> nextFrame(int, std::vector<InputEvent>& events) override {
        // Input while paused makes the site paint one frame at the paused time.
        if (clock_.paused() && events_.hasEvents()) clock_.forceFrame();
        if (!clock_.shouldRender()) return std::nullopt;
        if (pacer_ && !clock_.paused()) {
            // --fps F: F frames per second of wall time. Input or a control ends the wait early;
            // the frame then comes at its time on a later call.
            if (const double wait = pacer_->wait(monotonicNow()); wait > 0) {
                events_.waitForInput(wait);
                if (pacer_->wait(monotonicNow()) > 0) return std::nullopt;
            }
            pacer_->drawn(monotonicNow());
        }
        events_.takeEvents(events);
        const double now = monotonicNow();
        shownRate_.frame(now);
        return clock_.frame(now, localWallClockNow());
    }

    void present(SessionCore& s) override {
        events_.setCanvasSize(s.width(), s.height());
        presentToDefaultFramebuffer(s.output(PassId::Image), framebuffer_.width, framebuffer_.height);
        drawOverlay(s);
        (void)window_.present();
    }

    void idle(SessionCore& s) override {
        // Paused, or waiting for a shadertoy that compiles: keep the window's content and wait.
        reportScreenshots();
        if (s.running() && s.frame() > 0) {
            present(s);
        } else {
            clearDefaultFramebuffer(framebuffer_.width, framebuffer_.height);
            drawOverlay(s);
            (void)window_.present();
        }
        events_.waitForInput(0.05);
    }

    // The screenshots still being written, then said where they are.
    void finishScreenshots() {
        writer_.drain();
        reportScreenshots();
    }

private:
    static RealTimeClockOptions clockOptions(const SessionPlan& plan) {
        const SessionSettings& s = plan.options.settings;
        RealTimeClockOptions clock{s.fps, s.startTime, 1.0 / defaults::kRestartTimeDelta, std::nullopt};
        if (s.fps || plan.wallClock) clock.wallClockStart = plan.wallClock.value_or(localWallClockNow());
        return clock;
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
        events_.setTitle({s.name(), shownRate_.rate(), s.running() ? s.frame() - 1 : -1, clock_.time(), paused,
                          s.problems().empty() ? "" : formatDiagnostic(s.problems().front())});
    }

    // F12: the shown frame as NAME-YYYYMMDD-HHMMSS-frameN.png in --out's folder or the working
    // directory, written off the GL thread (a notice says where once it is written).
    Status screenshot(SessionCore& s) {
        if (!s.running() || s.frame() == 0) return Error("nothing is shown yet: no screenshot", Code::WindowScreenshot);
        fs::path folder = ".";
        if (plan_.output && plan_.output->kind().toFile) {
            const fs::path parent = plan_.output->pathFor(0).parent_path();
            if (!parent.empty()) folder = parent;
        }
        char stamp[32];
        const std::time_t now = std::time(nullptr);
        std::tm local{};
        localtime_r(&now, &local);
        std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
        const std::string base = fileSafe(s.name()) + "-" + stamp + "-frame" + std::to_string(s.frame() - 1);
        auto pixels = std::make_shared<std::vector<std::uint8_t>>();
        s.readRgba8(PassId::Image, *pixels);
        const int width = s.width(), height = s.height();
        writer_.submit([folder, base, pixels, width, height]() -> Result<fs::path> {
            // Two screenshots of one frame in one second (after a restart) get their own names.
            fs::path file = folder / (base + ".png");
            std::error_code ec;
            for (int n = 2; fs::exists(file, ec); ++n) file = folder / (base + "-" + std::to_string(n) + ".png");
            if (Status written = writePng(file, width, height, *pixels); !written) return written.error();
            return file;
        });
        return okStatus();
    }
    // The overlay (errors, F2 inspector) over the presented canvas: see drivers/window/Overlay.h.
    // Made when first needed: a window that never shows it starts as fast as before.
    Overlay* overlay() {
        if (overlay_ || overlayFailed_) return overlay_.get();
        if (Result<std::unique_ptr<Overlay>> made = Overlay::create(); made) {
            overlay_ = std::move(*made);
        } else {
            overlayFailed_ = true;
            for (const Diagnostic& d : made.error().diagnostics) observer_.notice(d);
        }
        return overlay_.get();
    }
    void toggleInspector() {
        if (!overlay()) return;
        overlay_->inspector().toggle();
        events_.setPointerCaptured(overlay_->inspector().open());
        observer_.notice(notice(overlay_->inspector().open() ? "inspector shown (F2 hides it; the mouse is the inspector's)"
                                                             : "inspector hidden (the mouse is the shader's again)",
                                Code::WindowInspector));
    }
    void drawOverlay(SessionCore& s) {
        if ((!overlay_ && s.problems().empty()) || !overlay()) return;
        std::vector<Diagnostic> notices;
        overlay_->draw(s, {framebuffer_.width, framebuffer_.height, events_.takePointer(),
                           {clock_.time(), clock_.measuredFrameRate(), clock_.paused()}},
                       notices);
        for (const Diagnostic& d : notices) observer_.notice(d);
    }
    void reportScreenshots() {
        for (Result<fs::path>& written : writer_.takeFinished()) {
            if (!written) {
                for (const Diagnostic& d : written.error().diagnostics) observer_.notice(d);
                continue;
            }
            Diagnostic d = notice("screenshot written", Code::WindowScreenshot);
            d.file = written->string();
            observer_.notice(d);
        }
    }

    WindowContext& window_;
    WindowEvents& events_;
    const SessionPlan& plan_;
    const SessionOptions& o_;
    ShadertoyWatcher& watcher_;
    BackgroundWriter writer_;
    SessionObserver& observer_;
    RealTimeClock clock_;
    ShownFrameRate shownRate_{monotonicNow()};
    std::optional<FramePacer> pacer_ =
        o_.settings.fps && !o_.unpaced ? std::optional<FramePacer>(*o_.settings.fps) : std::nullopt;
    GlSurface::Size framebuffer_;
    std::unique_ptr<Overlay> overlay_;  // none until needed, or when it cannot be made (said once)
    bool overlayFailed_ = false;
    bool titlePaused_ = false;
    double titleShownAt_ = -1;
};

}  // namespace

Result<SessionReport> runWindow(const SessionOptions& options, SessionObserver& observer, Watchdog* watchdog) {
    Result<SessionPlan> prepared = prepareSession(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    WindowOptions windowOptions;
    windowOptions.width = *prepared->options.settings.width;
    windowOptions.height = *prepared->options.settings.height;
    const std::string& name = prepared->shadertoy.manifest.name;
    windowOptions.title = name.empty() ? "toyhost" : name + " - toyhost";
    ShadertoyWatcher watcher(prepared->options.target, prepared->media, prepared->defines, prepared->shadertoy.manifest);
    Result<std::shared_ptr<WindowContext>> window = WindowContext::create(windowOptions);
    if (!window) return window.error();
    (*window)->releaseCurrent();  // the GL thread makes it current

    std::atomic<bool> done{false};
    std::optional<Result<SessionReport>> result;
    WindowEvents events(**window, [&] {
        if (!watchdog) return;
        // The first close starts the grace period; a second one while stopping ends at once.
        if (watchdog->stopRequested()) watchdog->quitAgain();
        else watchdog->requestStop(StopReason::Quit);
    });
    GlThread gl([&] {
        if (!prepared->options.outPattern) {  // the canvas is the framebuffer, in pixels
            const GlSurface::Size fb = events.framebufferSize();
            prepared->options.settings.width = fb.width;
            prepared->options.settings.height = fb.height;
        }
        {
            Result<std::unique_ptr<SessionCore>> session = SessionCore::start(std::move(*prepared), *window, observer, watchdog);
            if (session) {
                (void)(*window)->setSwapInterval((*session)->plan().options.unpaced ? 0 : 1);
                WindowDriver driver(**window, events, (*session)->plan(), watcher, observer);
                result = (*session)->run(driver);
                driver.finishScreenshots();
                // Closed before the shadertoy ever compiled: the run ends with why.
                if (*result && !(*session)->running() && !(*session)->problems().empty())
                    result = Result<SessionReport>(Error((*session)->problems()));
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
