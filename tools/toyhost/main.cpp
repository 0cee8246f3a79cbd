// toyhost: the command-line interface. Parses arguments, runs the job, prints what the library
// reports and chooses the exit code (0 success, 1 run failure, 2 bad usage, 128+signal when interrupted).
#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <unistd.h>

#include "capture/ImageStats.h"
#include "capture/ImageWriters.h"
#include "core/AtomicFile.h"
#include "export/ShadertoyExport.h"
#include "manifest/ManifestWriter.h"
#include "run/FrameClock.h"
#include "run/HeadlessRun.h"
#include "run/ProgressLine.h"

namespace {

using namespace toyhost;

// Set by SIGINT/SIGTERM: the run stops before its next frame and cleans up (a second signal
// kills the process at once).
volatile std::sig_atomic_t stopSignal = 0;
extern "C" void onStopSignal(int signal) {
    stopSignal = signal;
    std::signal(signal, SIG_DFL);
}

// Everything goes to stderr: stdout may be carrying raw frames (--out -).
class ConsoleObserver final : public RunObserver {
public:
    explicit ConsoleObserver(bool quiet) : show_(!quiet && isatty(STDERR_FILENO)) {}
    void notice(const std::string& line) override {
        if (shown_) std::cerr << "\r\033[K";
        shown_ = false;
        std::cerr << line << "\n";
    }
    bool stopRequested() const override { return stopSignal != 0; }
    void progress(const RunProgress& p) override {
        if (!show_) return;
        // At most five updates a second: a terminal write per frame would cost more than a fast
        // shader's frame.
        const auto now = std::chrono::steady_clock::now();
        const bool last = p.framesDone == p.frames;
        if (!last && shown_ && now - lastShown_ < std::chrono::milliseconds(200)) return;
        lastShown_ = now;
        shown_ = !last;
        if (last) std::cerr << "\r\033[K" << std::flush;
        else std::cerr << "\r\033[K" << formatProgressLine(p) << std::flush;
    }

private:
    bool show_;
    bool shown_ = false;
    std::chrono::steady_clock::time_point lastShown_;
};

bool parseSize(const std::string& text, int& w, int& h) {
    char x = 0, extra = 0;
    return std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) == 3 && (x == 'x' || x == 'X');
}

std::optional<PassId> parsePass(const std::string& text) {
    for (PassId id : {PassId::BufferA, PassId::BufferB, PassId::BufferC, PassId::BufferD, PassId::Image})
        if (text == passName(id)) return id;
    if (text.size() == 1 && text[0] >= 'A' && text[0] <= 'D') return bufferPass(text[0] - 'A');
    return std::nullopt;
}

// `toyhost import`: the export's passes as files, byte for byte, with a manifest binding them.
int importCommand(const std::string& source, const std::string& dir, bool force) {
    Result<std::string> text = readTextFile(source);
    Result<ManifestDesc> shadertoy = text ? parseShadertoyExport(*text, source) : Result<ManifestDesc>(text.error());
    if (!shadertoy) {
        std::cerr << "toyhost: " << shadertoy.error().message << "\n";
        return 1;
    }
    for (const std::string& line : shadertoy->notices) std::cerr << "toyhost: " << line << "\n";
    if (Status written = writeManifestFolder(*shadertoy, dir, force); !written) {
        std::cerr << "toyhost: " << written.error().message << "\n";
        return 1;
    }
    std::cerr << "toyhost: imported " << shadertoy->name << " into " << dir << " (" << shadertoy->passes.size()
              << (shadertoy->commonSource ? " passes + Common)" : " passes)") << "\n";
    return 0;
}

// `toyhost inspect`: one line per channel and file, for checking invariants of buffer dumps.
int inspectFilesCommand(const std::vector<std::string>& files, const Region& region) {
    for (const std::string& file : files) {
        Result<ImageF32> image = readExr(file);
        if (!image) {
            std::cerr << "toyhost: " << image.error().message << "\n";
            return 1;
        }
        Result<std::array<ChannelStats, 4>> stats = channelStats(*image, region);
        if (!stats) {
            std::cerr << "toyhost: " << file << ": " << stats.error().message << "\n";
            return 1;
        }
        std::printf("%s (%dx%d)\n", file.c_str(), image->width, image->height);
        const char* names = "RGBA";
        for (int c = 0; c < 4; ++c) {
            const ChannelStats& s = (*stats)[c];
            std::printf("  %c: sum %.9g mean %.9g min %.9g max %.9g nan %zu inf %zu\n", names[c], s.sum, s.mean, s.min,
                        s.max, s.nan, s.inf);
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"toyhost: run Shadertoy shaders unmodified, headless or in a window"};
    app.set_version_flag("--version", std::string("toyhost ") + TOYHOST_VERSION);
    app.require_subcommand(1);

    RunOptions options;
    std::string target, size = "800x450", capturePass = "Image", mouse, date;
    std::vector<std::string> mediaFiles;
    bool headless = false, quiet = false;

    CLI::App* run = app.add_subcommand("run", "Run a shadertoy described by a manifest");
    run->add_option("target", target, "Folder holding manifest.json, a manifest file, or a Shadertoy JSON export")->required();
    run->add_flag("--headless", headless, "Render without a window (EGL surfaceless; the only mode for now)");
    run->add_option("--size", size, "Canvas size WxH")->capture_default_str();
    run->add_option("--frames", options.frames, "Number of frames to render")->capture_default_str();
    run->add_option("--fps", options.fps, "Fixed frame rate: frame n has iTime = start + n/fps")->capture_default_str();
    run->add_option("--start-time", options.startTime, "iTime of frame 0, in seconds")->capture_default_str();
    run->add_option("--out", options.outPattern,
                    "Write captured frames: out/frame_%04d.png (8-bit, as shown) or .exr (32-bit float RGBA), "
                    "numbered by iFrame; a video movie.mp4|.webm|.mov|.mkv (through ffmpeg); or - for raw "
                    "frames on stdout: per frame width*height*4 bytes RGBA8, rows top first, no header");
    int captureMemoryMiB = static_cast<int>(options.captureMemoryBytes >> 20);
    std::string codec;
    int videoQuality = -1;
    run->add_option("--png-level", options.pngLevel, "PNG compression 0 (none) .. 9 (smallest); 1 is fast")
        ->capture_default_str();
    run->add_option("--codec", codec, "Video encoder (ffmpeg name); default libx264 (.mp4/.mov/.mkv), libvpx-vp9 (.webm)");
    run->add_option("--video-quality", videoQuality,
                    "Video constant rate factor, lower is better (default 18 for H.264, 31 for VP9)");
    run->add_option("--encoder-threads", options.encoderThreads,
                    "Threads encoding captured frames (default: cores - 1, at least 1)");
    run->add_option("--capture-memory", captureMemoryMiB,
                    "MiB of frames allowed to wait for the encoders; rendering waits beyond it")
        ->capture_default_str();
    run->add_flag("--sync-capture", options.syncCapture,
                  "Read back and encode each frame on the render thread (slower; the reference path)");
    run->add_flag("--finish-each-frame", options.finishEachFrame,
                  "Wait for the GPU after every frame (benchmarks; see docs/performance.md)");
    run->add_option("--capture-every", options.captureEvery, "Capture frames n with n % K == 0, and the last frame")
        ->capture_default_str();
    run->add_option("--capture-pass", capturePass, "Pass to capture: Image, \"Buffer A\" .. \"Buffer D\" (or A..D)")
        ->capture_default_str();
    run->add_option("--mouse", mouse, "Press the button at pixel X,Y (origin bottom-left) on frame 0 and hold it");
    run->add_option("--mouse-script", options.mouseScript, "JSON list of timed mouse events (see README)");
    run->add_option("--key-script", options.keyScript, "JSON list of timed key events (see README)");
    run->add_option("--media-file", mediaFiles, "Use FILE for a stock media id: ID=FILE (repeatable)");
    run->add_option("--media", options.mediaFolders,
                    "Folder with real stock media files, by hash or name (repeatable; also $TOYHOST_MEDIA)");
    run->add_option("--date", date, "iDate at frame 0, YYYY-MM-DDTHH:MM:SS (default: now, local time)");
    run->add_flag("--quiet", quiet, "No progress line");

    std::string importSource, importDir;
    bool importForce = false;
    CLI::App* import = app.add_subcommand("import", "Turn a Shadertoy JSON export into an editable manifest folder");
    import->add_option("export", importSource, "Shadertoy export (API {\"Shader\": ...} or site form)")->required();
    import->add_option("dir", importDir, "Folder to write manifest.json and the pass files into")->required();
    import->add_flag("--force", importForce, "Overwrite an existing manifest.json");

    std::vector<std::string> inspectFiles;
    std::string regionText;
    CLI::App* inspect = app.add_subcommand("inspect", "Print per-channel statistics of EXR buffer dumps");
    inspect->add_option("files", inspectFiles, "EXR files written by --out ... .exr")->required();
    inspect->add_option("--region", regionText, "X,Y,W,H in pixels, origin bottom-left (default: whole image)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }

    auto usage = [](const std::string& message) {
        std::cerr << "toyhost: " << message << "\n";
        return 2;
    };
    if (import->parsed()) return importCommand(importSource, importDir, importForce);
    if (inspect->parsed()) {
        Region region;
        if (!regionText.empty()) {
            char extra = 0;
            if (std::sscanf(regionText.c_str(), "%d,%d,%d,%d%c", &region.x, &region.y, &region.width, &region.height,
                            &extra) != 4)
                return usage("--region " + regionText + ": expected X,Y,W,H");
        }
        return inspectFilesCommand(inspectFiles, region);
    }
    options.target = target;
    if (const char* mediaFolder = std::getenv("TOYHOST_MEDIA"); mediaFolder && *mediaFolder)
        options.mediaFolders.emplace_back(mediaFolder);
    if (!parseSize(size, options.width, options.height)) return usage("--size " + size + ": expected WxH, e.g. 800x450");
    std::optional<PassId> pass = parsePass(capturePass);
    if (!pass) return usage("--capture-pass " + capturePass + ": expected Image or \"Buffer A\" .. \"Buffer D\"");
    options.capturePass = *pass;
    if (!mouse.empty()) {
        float x = 0, y = 0;
        char comma = 0, extra = 0;
        if (std::sscanf(mouse.c_str(), "%f%c%f%c", &x, &comma, &y, &extra) != 3 || comma != ',')
            return usage("--mouse " + mouse + ": expected X,Y in pixels");
        options.mouse = glm::vec2(x, y);
    }
    for (const std::string& entry : mediaFiles) {
        const size_t eq = entry.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == entry.size())
            return usage("--media-file " + entry + ": expected ID=FILE");
        options.mediaFiles.emplace_back(entry.substr(0, eq), entry.substr(eq + 1));
    }
    if (!date.empty()) {
        Result<double> wallClock = parseWallClock(date);
        if (!wallClock) return usage("--date: " + wallClock.error().message);
        options.wallClock = *wallClock;
    }
    (void)headless;  // headless is the only mode until the window backend lands
    if (captureMemoryMiB < 1) return usage("--capture-memory must be at least 1 (MiB)");
    options.captureMemoryBytes = static_cast<std::size_t>(captureMemoryMiB) << 20;
    if (!codec.empty()) options.video.codec = codec;
    if (videoQuality >= 0) options.video.quality = videoQuality;
    if (options.outPattern && *options.outPattern == "-" && isatty(STDOUT_FILENO))
        return usage("--out -: stdout is a terminal; redirect the raw frames to a file or a pipe");
    // A closed stdout (`--out - | head -c ...`) must end the run with a message, not kill it.
    std::signal(SIGPIPE, SIG_IGN);
    std::signal(SIGINT, onStopSignal);
    std::signal(SIGTERM, onStopSignal);

    ConsoleObserver observer(quiet);
    Result<RunReport> report = runHeadless(options, observer);
    if (!report) {
        std::cerr << "toyhost: " << report.error().message << "\n";
        return stopSignal ? 128 + stopSignal : 1;  // the shell's convention for a signal
    }
    const double fps = report->seconds > 0 ? report->framesRendered / report->seconds : 0;
    std::fprintf(stderr, "toyhost: %s: %d frames at %dx%d in %.3f s (%.1f frames/s, first frame after %.0f ms) on %s\n",
                 report->manifestName.c_str(), report->framesRendered, options.width, options.height,
                 report->seconds, fps, report->firstFrameSeconds * 1000.0, report->context.c_str());
    if (report->files.size() == 1)
        std::fprintf(stderr, "toyhost: wrote %s (%s)\n", report->files.front().c_str(),
                     formatBytes(report->bytesWritten).c_str());
    else if (!report->files.empty())
        std::fprintf(stderr, "toyhost: wrote %zu files (%s): %s .. %s\n", report->files.size(),
                     formatBytes(report->bytesWritten).c_str(), report->files.front().c_str(),
                     report->files.back().c_str());
    else if (options.outPattern && *options.outPattern == "-")
        std::fprintf(stderr, "toyhost: wrote %s of raw RGBA8 frames to stdout\n",
                     formatBytes(report->bytesWritten).c_str());
    return 0;
}
