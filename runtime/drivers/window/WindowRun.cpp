#include "drivers/window/WindowRun.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <memory>

#include "core/Defaults.h"
#include "core/Diagnostic.h"
#include "drivers/window/WindowContext.h"
#include "image/ImageWriters.h"
#include "input/InputEvent.h"
#include "input/WindowInput.h"
#include "player/Player.h"
#include "render/Present.h"
#include "session/AllProblems.h"
#include "session/FrameRecorder.h"
#include "session/ShadertoyWatcher.h"
#include "timing/FrameClock.h"
#include "timing/RealTimeClock.h"
#include "input/WindowControls.h"

namespace toyhost {

namespace {

namespace fs = std::filesystem;

double monotonicNow() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// What GLFW's callbacks collect between two frames, read by the loop on the same thread.
struct WindowInputState {
    WindowContext* window = nullptr;
    const Player* player = nullptr;  // the canvas size comes from it
    std::vector<InputEvent> events;  // for the next rendered frame, in order
    int buttonsDown = 0;
    bool controls[8] = {};           // indexed by Control: pressed since the last loop iteration

    void push(const InputEvent& event) {
        // Moves between two frames: only the last position matters (and the queue stays small
        // while paused).
        if (event.type == InputEvent::Type::MouseMove && !events.empty() &&
            events.back().type == InputEvent::Type::MouseMove) {
            events.back() = event;
            return;
        }
        events.push_back(event);
    }
    // The cursor (window coordinates, top-left origin) in canvas pixels as the site computes them,
    // taking the canvas's place in the framebuffer into account.
    glm::vec2 canvasPosition(double cx, double cy) const {
        const GlSurface::Size win = window->windowSize();
        const GlSurface::Size fb = window->framebufferSize();
        if (win.width <= 0 || win.height <= 0 || fb.width <= 0 || fb.height <= 0) return glm::vec2(0.0f);
        const int canvasW = player->width(), canvasH = player->height();
        const PresentRect r = presentRect(canvasW, canvasH, fb.width, fb.height);
        const double fx = cx * fb.width / win.width;
        const double fyTop = cy * fb.height / win.height;
        const double localYTop = fyTop - (fb.height - r.y - r.height);
        return siteMousePosition(fx - r.x, localYTop, r.width, r.height, canvasW, canvasH);
    }
};

WindowInputState& stateOf(GLFWwindow* window) {
    return *static_cast<WindowInputState*>(glfwGetWindowUserPointer(window));
}

void onCursor(GLFWwindow* window, double x, double y) {
    WindowInputState& s = stateOf(window);
    if (s.buttonsDown == 0) return;  // iMouse.xy moves only while the button is held
    const glm::vec2 p = s.canvasPosition(x, y);
    s.push(InputEvent::mouseMove(p.x, p.y));
}

void onButton(GLFWwindow* window, int, int action, int) {
    WindowInputState& s = stateOf(window);
    double x = 0, y = 0;
    glfwGetCursorPos(window, &x, &y);
    if (action == GLFW_PRESS) {
        if (s.buttonsDown++ == 0) {
            const glm::vec2 p = s.canvasPosition(x, y);
            s.push(InputEvent::mouseDown(p.x, p.y));
        }
    } else if (action == GLFW_RELEASE && s.buttonsDown > 0) {
        if (--s.buttonsDown == 0) s.push(InputEvent::mouseUp());
    }
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action == GLFW_REPEAT) return;  // the site ignores auto-repeat
    WindowInputState& s = stateOf(window);
    const Control control = controlForKey(key, mods);
    if (control != Control::None) {
        if (action == GLFW_PRESS) s.controls[static_cast<int>(control)] = true;
        return;
    }
    const int code = javascriptKeyCode(key);
    if (code == 0) return;
    s.push(action == GLFW_PRESS ? InputEvent::keyDown(code) : InputEvent::keyUp(code));
}

bool takeControl(WindowInputState& s, Control control) {
    bool& flag = s.controls[static_cast<int>(control)];
    const bool was = flag;
    flag = false;
    return was;
}

std::string fileSafe(std::string name) {
    for (char& c : name)
        if (c == '/' || c == '\\' || c == ':' || static_cast<unsigned char>(c) < 32) c = '_';
    return name.empty() ? std::string("toyhost") : name;
}

Diagnostic notice(std::string message, Code code, std::string file = {}) {
    Diagnostic d;
    d.severity = Severity::Notice;
    d.message = std::move(message);
    d.code = code;
    d.file = std::move(file);
    return d;
}

}  // namespace

Result<SessionReport> runWindow(const SessionOptions& options, SessionObserver& observer) {
    const auto started = std::chrono::steady_clock::now();
    Result<SessionPlan> prepared = prepareSession(options);
    if (!prepared) return withCompileProblems(options, prepared.error());
    SessionPlan& run = *prepared;
    const SessionOptions& o = run.options;
    for (const Diagnostic& line : run.plan.notices) observer.notice(line);

    WindowOptions windowOptions;
    windowOptions.width = *o.width;
    windowOptions.height = *o.height;
    windowOptions.title = run.plan.manifest.name.empty() ? "toyhost" : run.plan.manifest.name + " - toyhost";
    Result<std::shared_ptr<WindowContext>> madeWindow = WindowContext::create(windowOptions);
    if (!madeWindow) return madeWindow.error();
    std::shared_ptr<WindowContext> window = *madeWindow;

    // The canvas is the framebuffer (HiDPI: pixels, not window coordinates), except while
    // recording: a recording has one size, so the canvas stays at --size and is scaled to fit.
    const bool recording = run.output.has_value();
    const GlSurface::Size fb = window->framebufferSize();
    PlayerDesc desc;
    desc.width = recording ? *o.width : fb.width;
    desc.height = recording ? *o.height : fb.height;
    desc.floatImage = recording && run.output->format() == OutputFormat::Exr && o.capturePass == PassId::Image;
    desc.activity = observer.activity();
    desc.watchDraws = *o.frameTimeout > 0;
    const std::string manifestName = run.plan.manifest.name;
    const fs::path manifestFolder = run.plan.manifest.manifestPath.parent_path();
    std::optional<ShadertoyWatcher> watcher;
    watcher.emplace(o.target, o.media, run.plan.manifest);
    Result<std::unique_ptr<Player>> made = Player::create(window, std::move(run.plan), desc);
    if (!made) return made.error();
    Player& player = **made;
    (void)window->setSwapInterval(1);

    std::unique_ptr<FrameRecorder> recorder;
    if (recording) {
        Result<std::unique_ptr<FrameRecorder>> created = FrameRecorder::create(recorderSettings(run, observer.activity()), player);
        if (!created) return created.error();
        recorder = std::move(*created);
    }

    WindowInputState input;
    input.window = window.get();
    input.player = &player;
    input.events.reserve(256);
    glfwSetWindowUserPointer(window->handle(), &input);
    glfwSetCursorPosCallback(window->handle(), onCursor);
    glfwSetMouseButtonCallback(window->handle(), onButton);
    glfwSetKeyCallback(window->handle(), onKey);

    RealTimeClockOptions clockOptions;
    clockOptions.fixedFps = o.fps;
    clockOptions.startTime = o.startTime;
    clockOptions.nominalFps = 1.0 / defaults::kRestartTimeDelta;
    RealTimeClock clock(clockOptions, monotonicNow());
    const double wallStart = o.wallClock ? *o.wallClock : localWallClockNow();

    SessionReport report;
    report.manifestName = manifestName;
    report.context = window->describe();
    int rendered = 0;       // frames rendered since the window opened (captured files are numbered so)
    std::string lastError;  // shown in the title until a reload succeeds
    double lastTitle = -1;
    bool interrupted = false;
    RunProgress progress;
    progress.frames = *o.frames;
    const auto loopStart = std::chrono::steady_clock::now();

    auto showProblems = [&](const std::vector<Diagnostic>& problems) {
        for (const Diagnostic& d : problems) observer.notice(d);
        if (!problems.empty()) {
            const Diagnostic& first = problems.front();
            lastError = formatDiagnostic(first);
        }
    };

    while (true) {
        if (*o.frames > 0 && rendered >= *o.frames) break;
        if (window->closeRequested()) break;
        if (observer.stopRequested()) {
            interrupted = true;
            break;
        }
        if (clock.shouldRender()) glfwPollEvents();
        else glfwWaitEventsTimeout(0.05);  // paused: nothing to render, wake for input and reloads

        // Controls.
        const double now = monotonicNow();
        if (takeControl(input, Control::Help)) observer.notice(notice(controlsHelp(), Code::WindowHelp));
        if (takeControl(input, Control::Quit)) window->requestClose();
        if (takeControl(input, Control::Restart)) {
            player.restart();
            clock.restart(now);
        }
        if (takeControl(input, Control::Pause)) clock.setPaused(!clock.paused(), now);
        if (takeControl(input, Control::Step)) clock.stepOnce();
        if (takeControl(input, Control::Fullscreen)) window->toggleFullscreen();
        if (takeControl(input, Control::Screenshot) && player.frame() > 0) {
            const fs::path folder = recording && !run.output->streamed() && run.output->format() != OutputFormat::RawStream
                                        ? run.output->pathFor(0).parent_path()
                                        : manifestFolder;
            char name[64];
            std::snprintf(name, sizeof name, "-frame%06d.png", player.frame() - 1);
            const fs::path file = (folder.empty() ? fs::path(".") : folder) / (fileSafe(manifestName) + name);
            std::vector<std::uint8_t> pixels;
            player.readRgba8(PassId::Image, pixels);
            Status written = writePng(file, player.width(), player.height(), pixels);
            if (written) observer.notice(notice("screenshot written", Code::WindowScreenshot, file.string()));
            else showProblems(written.error().diagnostics);
        }
        if (window->closeRequested()) break;

        // The canvas follows the framebuffer (not while recording).
        const GlSurface::Size size = window->framebufferSize();
        if (!recording && size.width > 0 && size.height > 0 &&
            (size.width != player.width() || size.height != player.height())) {
            if (Status resized = player.resize(size.width, size.height); !resized) showProblems(resized.error().diagnostics);
        }

        // Hot reload.
        if (std::optional<Result<PlayerPlan>> next = watcher->take()) {
            if (!*next) {
                showProblems(next->error().diagnostics);
            } else {
                ReloadReport reloaded = player.reload(std::move(**next));
                showProblems(reloaded.problems);
                if (reloaded.applied && reloaded.problems.empty()) {
                    lastError.clear();
                    std::string passes;
                    for (const std::string& pass : reloaded.recompiled) passes += (passes.empty() ? "" : ", ") + pass;
                    observer.notice(notice(reloaded.structureChanged ? "reloaded (new structure, restarted): " + passes
                                                                     : "reloaded: " + passes,
                                           Code::WindowReload));
                }
                if (reloaded.structureChanged && reloaded.applied) {
                    player.restart();
                    clock.restart(now);
                }
            }
        }

        if (clock.shouldRender()) {
            FrameTime time = clock.frame(monotonicNow(), localWallClockNow());
            if (o.fps || o.wallClock) time.date = dateAt(wallStart + (time.time - o.startTime));
            player.step(time, input.events);
            input.events.clear();
            if (recorder) {
                const bool captured = isCapturedFrame(rendered, *o.frames, *o.captureEvery);
                Status saved = captured ? recorder->capture(player, rendered) : recorder->poll();
                if (!saved) return saved.error();
                if (captured && run.output->format() != OutputFormat::Video &&
                    run.output->format() != OutputFormat::RawStream)
                    report.files.push_back(run.output->pathFor(rendered));
            }
            if (rendered == 0)
                report.firstFrameSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            ++rendered;
            progress.framesDone = rendered;
            progress.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
            progress.bytesWritten = recorder ? recorder->bytesWritten() : 0;
            observer.progress(progress);
        }
        presentToDefaultFramebuffer(player.output(PassId::Image), size.width, size.height);
        (void)window->present();

        if (now - lastTitle > 0.25) {
            lastTitle = now;
            char text[160];
            std::snprintf(text, sizeof text, " | %.1f fps | iFrame %d | iTime %.2f", clock.frameRate(), player.frame() - 1,
                          clock.time());
            std::string title = (manifestName.empty() ? std::string("toyhost") : manifestName) + text;
            if (clock.paused()) title += " | paused (F6)";
            if (!lastError.empty()) title += " | " + lastError;
            window->setTitle(title);
        }
    }

    if (interrupted)
        return Error("interrupted after " + std::to_string(rendered) + " frames", Code::Interrupted);
    if (recorder) {
        if (Status finished = recorder->finish(); !finished) return finished.error();
        report.bytesWritten = recorder->bytesWritten();
        report.encoderThreads = recorder->encoderThreads();
        if (recorder->droppedFrames() > 0) {
            std::vector<fs::path> written;
            for (const fs::path& file : report.files)
                if (std::error_code ec; fs::exists(file, ec)) written.push_back(file);
            report.files = std::move(written);
        }
        if (recorder->droppedFrames() > 0)
            observer.notice(notice(std::to_string(recorder->droppedFrames()) +
                                       " frames were not recorded: the encoders were behind and real-time mode "
                                       "does not wait for them (use --fps for every frame)",
                                   Code::CaptureDropped));
        if (run.output->format() == OutputFormat::Video) report.files.push_back(run.output->pathFor(0));
    }
    player.finish();
    report.framesRendered = rendered;
    report.width = player.width();
    report.height = player.height();
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
    return report;
}

}  // namespace toyhost
