#include "run/HeadlessRun.h"

#include <chrono>
#include <map>
#include <memory>

#include "capture/OutputPattern.h"
#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "gl/EglSurfacelessContext.h"
#include "graph/PassGraph.h"
#include "input/InputScript.h"
#include "input/InputScriptPlayer.h"
#include "input/KeyboardState.h"
#include "input/MouseState.h"
#include "export/LoadShadertoy.h"
#include "media/MediaResolver.h"
#include "render/Renderer.h"
#include "run/ChannelImages.h"
#include "run/FrameCapture.h"
#include "run/FrameClock.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {

int countCaptured(int frames, int every) {
    int n = 0;
    for (int f = 0; f < frames; ++f) n += isCapturedFrame(f, frames, every);
    return n;
}

// Everything a run needs that can be checked without GL.
struct PreparedRun {
    ManifestDesc manifest;
    PassGraph graph;
    std::optional<OutputPattern> output;
    MouseScript mouse;
    KeyScript keys;
    MediaResolver media;
};

Result<PreparedRun> prepare(const RunOptions& o) {
    if (o.width < 1 || o.height < 1 || o.width > 16384 || o.height > 16384)
        return Error{"--size must be between 1x1 and 16384x16384"};
    if (o.frames < 1) return Error{"--frames must be at least 1"};
    if (!(o.fps > 0)) return Error{"--fps must be positive"};
    if (o.captureEvery < 1) return Error{"--capture-every must be at least 1"};
    if (o.mouse && o.mouseScript) return Error{"--mouse and --mouse-script cannot be combined"};
    if (o.pngLevel < 0 || o.pngLevel > 9) return Error{"--png-level must be 0..9"};
    if (o.encoderThreads < 0 || o.encoderThreads > 1024)
        return Error{"--encoder-threads must be 0 (automatic) to 1024"};
    if (o.captureMemoryBytes == 0) return Error{"--capture-memory must be positive"};
    if (o.video.quality && (*o.video.quality < 0 || *o.video.quality > 63))
        return Error{"--video-quality must be 0..63 (a constant rate factor; lower is better)"};

    Result<ManifestDesc> manifest = loadShadertoy(o.target);
    if (!manifest) return manifest.error();
    PreparedRun run{std::move(*manifest), {}, std::nullopt, {}, {}, {}};
    run.graph = buildPassGraph(run.manifest);

    if (!run.manifest.find(o.capturePass))
        return Error{std::string("--capture-pass ") + passName(o.capturePass) + ": " +
                     run.manifest.manifestPath.string() + " has no such pass"};
    if (o.outPattern) {
        Result<OutputPattern> pattern = OutputPattern::parse(*o.outPattern);
        if (!pattern) return pattern.error();
        if (!pattern->numbered() && !pattern->streamed() && countCaptured(o.frames, o.captureEvery) > 1)
            return Error{"--out " + *o.outPattern + ": more than one frame is captured, so the "
                         "pattern needs a frame number placeholder such as %04d"};
        if (pattern->format() == OutputFormat::Video && !findExecutable("ffmpeg"))
            return Error{"--out " + *o.outPattern + ": video needs ffmpeg, which is not in PATH "
                         "(Debian: apt-get install ffmpeg)"};
        run.output = std::move(*pattern);
    }
    if ((o.video.codec || o.video.quality) && (!run.output || run.output->format() != OutputFormat::Video))
        return Error{"--codec and --video-quality apply only to a video --out (.mp4, .webm, .mov, .mkv)"};
    if (o.mouse) run.mouse = mouseHeldAt(o.mouse->x, o.mouse->y);
    if (o.mouseScript) {
        Result<std::string> text = readTextFile(*o.mouseScript);
        if (!text) return withContext("--mouse-script", text.error());
        Result<MouseScript> script = parseMouseScript(*text, o.mouseScript->string());
        if (!script) return script.error();
        run.mouse = std::move(*script);
    }
    if (o.keyScript) {
        Result<std::string> text = readTextFile(*o.keyScript);
        if (!text) return withContext("--key-script", text.error());
        Result<KeyScript> script = parseKeyScript(*text, o.keyScript->string());
        if (!script) return script.error();
        run.keys = std::move(*script);
    }
    for (const auto& [id, file] : run.manifest.mediaOverrides) run.media.setOverride(id, file);
    for (const auto& [id, file] : o.mediaFiles) {
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) return Error{"--media-file " + id + ": " + file.string() + ": file not found"};
        run.media.setOverride(id, file);
    }
    for (const fs::path& folder : o.mediaFolders) run.media.addSearchFolder(folder);
    return run;
}

}  // namespace

Result<RunReport> runHeadless(const RunOptions& o, RunObserver& observer) {
    using Clock = std::chrono::steady_clock;
    const auto started = Clock::now();
    Result<PreparedRun> prepared = prepare(o);
    if (!prepared) return prepared.error();
    PreparedRun& run = *prepared;
    for (const std::string& line : run.manifest.notices) observer.notice("toyhost: " + line);

    Result<std::unique_ptr<GlContext>> context = createEglSurfacelessContext();
    if (!context) return context.error();

    RendererOptions renderOptions;
    renderOptions.width = o.width;
    renderOptions.height = o.height;
    renderOptions.floatImageTarget =
        run.output && run.output->format() == OutputFormat::Exr && o.capturePass == PassId::Image;
    ChannelImages images(run.media, [&](const std::string& line) { observer.notice(line); });
    Result<std::unique_ptr<Renderer>> renderer =
        Renderer::create(run.manifest, run.graph, renderOptions, std::ref(images));
    if (!renderer) return renderer.error();

    std::unique_ptr<FrameCapture> capture;
    if (run.output) {
        CaptureSettings settings;
        settings.output = *run.output;
        settings.pass = o.capturePass;
        settings.synchronous = o.syncCapture;
        settings.pngLevel = o.pngLevel;
        settings.encoderThreads = o.encoderThreads;
        settings.memoryCapBytes = o.captureMemoryBytes;
        settings.video = o.video;
        settings.fps = o.fps;
        settings.rawStreamFd = o.rawStreamFd;
        Result<std::unique_ptr<FrameCapture>> made = FrameCapture::create(settings, **renderer);
        if (!made) return made.error();
        capture = std::move(*made);
    }

    RunReport report;
    report.manifestName = run.manifest.name;
    report.context = (*context)->describe();

    FrameClock clock(o.fps, o.startTime, o.wallClock ? *o.wallClock : localWallClockNow());
    MouseState mouse;
    KeyboardState keyboard;
    MouseScriptPlayer mousePlayer(std::move(run.mouse));
    KeyScriptPlayer keyPlayer(std::move(run.keys));
    std::uint64_t uploadedKeyboard = keyboard.revision();
    RunProgress progress;
    progress.frames = o.frames;

    const auto loopStart = Clock::now();
    for (int frame = 0; frame < o.frames; ++frame) {
        if (observer.stopRequested())
            return Error{"interrupted after " + std::to_string(frame) + " of " + std::to_string(o.frames) + " frames"};
        const double time = clock.time(frame);
        mousePlayer.applyBeforeFrame(frame, time, mouse);
        keyPlayer.applyBeforeFrame(frame, time, keyboard);
        if (keyboard.revision() != uploadedKeyboard) {
            (*renderer)->updateKeyboard(keyboard.texels());
            uploadedKeyboard = keyboard.revision();
        }
        FrameUniforms uniforms;
        uniforms.frame = frame;
        uniforms.time = static_cast<float>(time);
        uniforms.timeDelta = static_cast<float>(clock.timeDelta());
        uniforms.frameRate = static_cast<float>(o.fps);
        uniforms.mouse = mouse.uniform();
        uniforms.date = clock.date(frame);
        const bool captured = run.output && isCapturedFrame(frame, o.frames, o.captureEvery);
        // Nothing reads the Image pass, so a run that captures renders it only on the frames it
        // captures: long simulations captured every K frames run at buffer speed. A run without
        // --out renders every pass of every frame (a dry run, and the render-only benchmark).
        (*renderer)->renderFrame(uniforms, !run.output || (captured && o.capturePass == PassId::Image));

        if (captured) {
            if (Status saved = capture->capture(**renderer, frame); !saved) return saved.error();
        } else if (capture) {
            if (Status polled = capture->poll(); !polled) return polled.error();
        }
        mouse.endFrame();
        keyboard.endFrame();  // its change is uploaded before the next frame renders
        // Frame 0 waits for the GPU once so that the time to the first frame is real.
        if (o.finishEachFrame || frame == 0) (*renderer)->finish();
        if (frame == 0) report.firstFrameSeconds = std::chrono::duration<double>(Clock::now() - started).count();
        report.framesRendered = frame + 1;
        progress.framesDone = frame + 1;
        progress.seconds = std::chrono::duration<double>(Clock::now() - loopStart).count();
        progress.bytesWritten = capture ? capture->bytesWritten() : 0;
        observer.progress(progress);
    }
    if (capture) {
        if (Status finished = capture->finish(); !finished) return finished.error();
        report.bytesWritten = capture->bytesWritten();
        report.encoderThreads = capture->encoderThreads();
    }
    (*renderer)->finish();  // the reported time includes the GPU's work
    report.seconds = std::chrono::duration<double>(Clock::now() - loopStart).count();
    if (run.output && run.output->format() != OutputFormat::RawStream) {
        for (int frame = 0; frame < o.frames; ++frame) {
            if (!isCapturedFrame(frame, o.frames, o.captureEvery)) continue;
            report.files.push_back(run.output->pathFor(frame));
            if (run.output->streamed()) break;
        }
    }
    return report;
}

}  // namespace toyhost
