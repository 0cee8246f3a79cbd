#include <cmath>
#include <cstdint>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <poll.h>
#include <unistd.h>

#include "Commands.h"
#include "Console.h"
#include "core/AtomicFile.h"
#include "core/Defaults.h"
#include "core/NumberText.h"
#include "drivers/headless/HeadlessDriver.h"
#include "drivers/window/WindowContext.h"
#include "drivers/window/WindowDriver.h"
#include "manifest/CodeShadertoy.h"
#include "session/StopSignals.h"

namespace toyhost::cli {

namespace {

std::optional<PassId> parsePass(const std::string& text) {
    for (PassId id : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD, PassId::CubeA, PassId::Image})
        if (text == passName(id)) return id;
    if (text.size() == 1 && text[0] >= 'A' && text[0] <= 'D') return bufferPass(text[0] - 'A');
    return std::nullopt;
}

// The stop a signal asked for while standard input was read: nothing runs, and the text read so
// far (cut anywhere) is not compiled.
Error stoppedReadingStdin() {
    return Error(std::string(stopSignalName(stopSignal())) +
                     " while the Image code was read from standard input: stopped, nothing was run",
                 Code::Interrupted);
}

// `toyhost run -`: the Image pass's code from standard input, read whole before the run starts.
// The read waits in poll() beside the stop signals' pipe (session/StopSignals.h): their handler
// restarts a blocked read() (SA_RESTART), so a pipe whose writer never closes once held the
// process until SIGKILL.
Result<std::string> readImageCodeFromStdin(const GlProcess& process) {
    if (process.closedAtStart[STDIN_FILENO]) return Error("standard input is closed: give the Image code through a pipe", Code::Usage);
    if (isatty(STDIN_FILENO))
        return Error("'-' reads the Image pass's code from standard input, which is a terminal: pipe a file in "
                     "(cat image.glsl | toyhost run -) or give the file",
                     Code::Usage);
    std::string code;
    char block[65536];
    for (;;) {
        pollfd ready[2] = {{STDIN_FILENO, POLLIN, 0}, {stopSignalFd(), POLLIN, 0}};
        if (stopSignal()) return stoppedReadingStdin();
        if (::poll(ready, ready[1].fd >= 0 ? 2 : 1, -1) < 0 && errno != EINTR)
            return Error(std::string("waiting for the Image code on standard input: ") + std::strerror(errno), Code::IoRead);
        if (stopSignal()) return stoppedReadingStdin();  // its byte stays in the pipe: said once, here
        if (ready[0].revents == 0) continue;
        const ssize_t got = ::read(STDIN_FILENO, block, sizeof block);
        if (got == 0) break;
        if (got < 0) {
            if (errno == EINTR || errno == EAGAIN) continue;
            return Error(std::string("reading the Image code from standard input: ") + std::strerror(errno), Code::IoRead);
        }
        code.append(block, static_cast<std::size_t>(got));
        if (code.size() > kDefaultReadLimitBytes)
            return Error("standard input holds more than " + std::to_string(kDefaultReadLimitBytes >> 20) +
                             " MiB: that is not a shader",
                         Code::IoTooLarge);
    }
    // A signal that also ended the writer (Ctrl-C in `cat | toyhost run -`) may come as the end of
    // the input: the text may be cut, and is not run.
    if (stopSignal()) return stoppedReadingStdin();
    return code;
}

}  // namespace

void RunCommand::define(CLI::App& run) {
    const std::string defaultSize = std::to_string(defaults::kCanvasWidth) + "x" + std::to_string(defaults::kCanvasHeight);
    run.add_option("target", target_,
                   "Folder holding manifest.json, a manifest file, a Shadertoy JSON export, a lone .glsl/.frag file (an "
                   "Image-only shadertoy, with the common.glsl next to it as Common), or - for the Image code on "
                   "standard input")
        ->required();
    run.add_flag("--window", window_,
                 "Open a window (GLFW, OpenGL ES 3) and run in real time with mouse and keyboard; the default when "
                 "$DISPLAY or $WAYLAND_DISPLAY is set. Keys: F1 help, F2 inspector, F5/Ctrl+R restart, F6/Pause pause, F7 step, "
                 "F11 fullscreen, F12 screenshot, Esc/Ctrl+Q quit; hot reload is always on");
    run.add_flag("--headless", headless_, "Render without a window (EGL, no display needed); the default without a display");
    run.add_flag("--watch", watch_,
                 "Headless: render the frames again whenever a file of the shadertoy changes, until Ctrl-C");
    flags_.define(run, SessionFlags::All);
    run.add_flag("--unpaced", unpaced_,
                 "Window with --fps F: draw frames as fast as the display allows (no vsync) instead of F per second "
                 "of wall time; iTime still advances 1/F per frame, so the preview runs faster than the recording");
    run.add_flag("--paced", paced_,
                 "Headless: draw the frames at the --fps rate in wall time (e.g. to feed a live stream) instead of as "
                 "fast as the machine can; the frames are the same");
    sampling_.define(run);
    run.add_option("--frames", frames_,
                   "Frames to render (default " + std::to_string(defaults::kFrames) + "; in a window: until closed)");
    run.add_option("--out", options_.outPattern,
                   "Write captured frames: out/frame_%04d.png (8-bit, as shown) or .exr (32-bit float RGBA), "
                   "numbered by iFrame; a video movie.mp4|.webm|.mov|.mkv (through ffmpeg); or - for raw "
                   "frames on stdout: per frame width*height*4 bytes RGBA8, rows top first, no header");
    run.add_option("--png-level", pngLevel_,
                   "PNG compression 0 (stored) .. 9 (smallest) (default " + std::to_string(defaults::kPngLevel) +
                       ", fastest compression); 1: toyhost's fast path (sampled filter, runs only); 2: libdeflate 1, "
                       "adaptive filter; 3-5: Up/Paeth filters; 6-9: adaptive filters, slower deflate "
                       "(docs/performance.md)");
    run.add_option("--exr-compression", exrCompression_,
                   "EXR compression: " + exrCompressionNames() +
                       " (default none: the site's export; none..piz are lossless, pxr24 keeps 24 bits of a float, "
                       "b44/b44a/dwaa/dwab are lossy)");
    run.add_flag("--exr-half", options_.exr.half, "EXR channels as 16-bit half floats instead of exact 32-bit floats");
    run.add_option("--codec", codec_,
                   "Video encoder (ffmpeg name); default libx264 (.mp4/.mov/.mkv), libvpx-vp9 (.webm); auto: a "
                   "hardware H.264 encoder that works here (h264_nvenc, h264_vaapi, h264_qsv: a test encode at "
                   "start), else libx264 -preset veryfast");
    run.add_option("--video-preset", videoPreset_,
                   "ffmpeg -preset for libx264 and the hardware encoders (libx264: ultrafast .. veryslow; default "
                   "medium, veryfast with --codec auto)");
    run.add_option("--video-quality", videoQuality_,
                   "Video constant rate factor, lower is better (default 18 for H.264, 31 for VP9)");
    run.add_option("--encoder-threads", encoderThreads_, "Threads encoding captured frames (default: cores - 1, at least 1, growing to one per core while "
                   "rendering outruns the encoders)");
    run.add_option("--capture-memory", captureMemoryMiB_,
                   "MiB of frames allowed to wait for the encoders; rendering waits beyond it (default " +
                       std::to_string(defaults::kCaptureMemoryMiB) + ")");
    run.add_flag("--sync-capture", options_.syncCapture,
                 "Read back and encode each frame on the render thread (slower; the reference path)");
    run.add_flag("--finish-each-frame", options_.finishEachFrame,
                 "Wait for the GPU after every frame (benchmarks; see docs/performance.md)");
    run.add_option("--capture-every", captureEvery_, "Capture frames n with n % K == 0, and the last frame (default 1)");
    run.add_option("--capture-pass", capturePass_,
                   "Pass to capture: Image (default), \"Buffer A\" .. \"Buffer D\" (or A..D), or \"Cube A\" (its six "
                   "faces side by side, +X -X +Y -Y +Z -Z, each 1024 wide)");
    run.add_option("--webcam", options_.webcam,
                   "What webcam channels show: a V4L2 camera (/dev/video0) or a video file (default: a moving stand-in)");
    run.add_option("--mic", options_.mic,
                   "What mic channels hear: an audio file, or live: alsa:DEVICE (alsa:default, alsa:hw:0), "
                   "pulse:DEVICE, lavfi:GRAPH (default: the spectrum the site shows without audio)");
    run.add_option("--tile", options_.tile,
                   "Draw Image in tiles of at most SIDE x SIDE pixels with iResolution the whole canvas, and write "
                   "PNG/EXR band by band (stills larger than a framebuffer; a --size beyond " +
                       std::to_string(defaults::kMaxCanvasSide) + " is tiled without it, with tiles of " +
                       std::to_string(defaults::kTileSide) + "); shadertoys without buffers only");
    run.add_option("--checkpoint", options_.checkpoint,
                   "Write the run's full state (every buffer, iFrame, time, mouse, keys) to FILE, atomically: "
                   "every --checkpoint-every frames, when interrupted and at the end");
    run.add_option("--checkpoint-every", options_.checkpointEvery, "Frames between checkpoints (with --checkpoint)");
    run.add_option("--resume", options_.resume,
                   "Continue from a --checkpoint FILE: the frames after it are byte-identical to an uninterrupted run");
    run.add_option("--frame-range", frameRange_,
                   "A:B: capture only frames A..B-1 of the run (earlier frames are simulated without capture; "
                   "numbering and iTime as in the whole run)");
    run.add_option("--shard", shard_,
                   "i/n: capture the i-th of n equal contiguous parts of the frames (i from 0), for render farms "
                   "(docs/farm.md)");
    run.add_flag("--check-finite", options_.checkFinite,
                 "Read every buffer back after every frame and warn at the first NaN/Inf, naming the pass and the "
                 "frame (without it: buffers are checked after the last frame and in captured EXR frames)");
    run.add_flag("--quiet", quiet_, "No progress line and no notices (warnings and errors still print)");
    // Numbers are read as decimal text by every command (readNumbersAsDecimal, main.cpp); ranges
    // beyond what the type holds are checked by prepareSession, which also serves library callers.
}

int RunCommand::execute(const GlProcess& process) {
    SessionOptions& o = options_;
    o.target = target_;
    if (target_ == "-") {
        Result<std::string> code = readImageCodeFromStdin(process);
        if (!code) return fail(code.error());
        std::error_code ec;
        o.shadertoy = std::make_shared<const ManifestDesc>(
            imageOnlyShadertoy("stdin", std::filesystem::current_path(ec) / "stdin", PassCode{std::move(*code), "stdin", "stdin"}));
    }
    if (Status given = flags_.applyTo(o.settings, o.mouse); !given) return fail(given.error());
    sampling_.applyTo(o.settings);
    o.frames = frames_;
    o.captureEvery = captureEvery_;
    o.pngLevel = pngLevel_;
    if (encoderThreads_) o.encoderThreads = *encoderThreads_;
    if (captureMemoryMiB_) {
        if (*captureMemoryMiB_ < 1) return usage("--capture-memory must be at least 1 (MiB)");
        o.captureMemoryBytes = static_cast<std::size_t>(*captureMemoryMiB_) << 20;
    }
    if (!capturePass_.empty()) {
        std::optional<PassId> pass = parsePass(capturePass_);
        if (!pass) return usage("--capture-pass " + capturePass_ + ": expected Image, \"Buffer A\" .. \"Buffer D\" or \"Cube A\"");
        o.capturePass = *pass;
    }
    o.eglPlatform = process.eglPlatform;
    o.startedAt = process.startedAt;
    // Two whole numbers as every number is read (core/NumberText.h), or the usage message.
    auto pair = [](const std::string& text, const char* separator, std::optional<std::pair<int, int>>& out) {
        const WholeNumbers read = wholeNumbersIn(text, separator, 2, 0, INT32_MAX);
        if (read.problem.empty()) out = std::pair{static_cast<int>(read.values[0]), static_cast<int>(read.values[1])};
        return read.problem;
    };
    if (!frameRange_.empty())
        if (std::string problem = pair(frameRange_, ":", o.frameRange); !problem.empty())
            return usage("--frame-range " + frameRange_ + ": expected A:B (frames A to B-1): " + problem);
    if (!shard_.empty())
        if (std::string problem = pair(shard_, "/", o.shard); !problem.empty())
            return usage("--shard " + shard_ + ": expected i/n (part i of n, from 0): " + problem);
    if (!codec_.empty()) o.video.codec = codec_;
    if (!videoPreset_.empty()) o.video.preset = videoPreset_;
    if (!exrCompression_.empty()) {
        const std::optional<ExrCompression> compression = exrCompressionNamed(exrCompression_);
        if (!compression)
            return usage("--exr-compression " + exrCompression_ + ": expected one of " + exrCompressionNames());
        o.exr.compression = *compression;
    }
    if (videoQuality_) o.video.quality = *videoQuality_;
    if (o.outPattern && *o.outPattern == "-" && process.closedAtStart[STDOUT_FILENO])
        return usage("--out -: stdout is closed; give it a file or a pipe (or --out frame_%04d.png)");
    if (o.outPattern && *o.outPattern == "-" && isatty(STDOUT_FILENO))
        return usage("--out -: stdout is a terminal; redirect the raw frames to a file or a pipe");

    if (window_ && headless_) return usage("--window and --headless cannot be combined");
    const bool windowMode = window_ || (!headless_ && displayAvailable());
    if (windowMode && watch_) return usage("--watch is for headless runs; a window always reloads changed files");
    if (windowMode && o.outPattern && *o.outPattern == "-")
        return usage("--out - (raw frames on stdout) is for headless runs");
    if (unpaced_ && !windowMode) return usage("--unpaced is for a window: headless runs are never paced");
    if (unpaced_ && !o.settings.fps)
        return usage("--unpaced goes with --fps: without it a window runs in real time, one frame per display refresh");
    o.interactive = windowMode;
    o.watch = watch_;
    if (paced_ && windowMode) return usage("--paced is for headless runs: a window with --fps is paced already");
    o.unpaced = unpaced_;
    o.paced = paced_;

    // A window's events are handled on this (the main) thread and it renders on a GL thread of its
    // own; headless runs render on a GL thread.
    if (windowMode) return runSession(o, quiet_, runWindow);
    int code = kExitOk;
    runOnGlThread([&] { code = runSession(o, quiet_, runHeadless); });
    return code;
}

}  // namespace toyhost::cli
