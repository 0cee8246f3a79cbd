#include "session/SessionOptions.h"

#include <cmath>

#include <toyhost/Shards.h>

#include "capture/FrameStream.h"
#include "core/AtomicFile.h"
#include "core/ChildProcess.h"
#include "core/Defaults.h"
#include "capture/SoundFile.h"
#include "capture/VideoEncoderChoice.h"
#include "export/LoadShadertoy.h"
#include "session/SettingChecks.h"
#include "timing/FrameClock.h"

#include <algorithm>
#include <type_traits>
#include <cctype>

namespace toyhost {
namespace fs = std::filesystem;

namespace {
int countCaptured(int first, int end, int frames, int every) {
    if (frames == 0) return 2;  // no end: as many as the user lets run
    int n = 0;
    for (int f = first; f < end && n < 2; ++f) n += FrameStream::captured(f, frames, every);
    return n;
}

Error usage(std::string message) { return Error(std::move(message), Code::Usage); }
}  // namespace

namespace {
// A row's fallback (toyhost/Settings.h): a toyhost::Defaults member, or `initial`, the field's own
// initial value. A fallback that names no member does not compile.
struct NoFallback {};
struct Fallbacks : Defaults {
    NoFallback initial;
};
template <class Setting, class V>
void fillFallback(Setting& setting, const V& value) {
    if constexpr (!std::is_same_v<V, NoFallback>)
        if (!setting) setting = value;
}
}  // namespace

SessionOptions withDefaults(SessionOptions o) {
    SessionSettings& s = o.settings;
    // A window: no fps means real time, and a frame has no time limit.
    const bool realTime = o.interactive && !s.fps;
    if (o.interactive && !s.frameTimeout) s.frameTimeout = 0.0;
    const Fallbacks fallbacks{};
#define TOYHOST_FILL_FALLBACK(Type, member, key, initial, fallback) fillFallback(s.member, fallbacks.fallback);
    TOYHOST_SESSION_SETTINGS(TOYHOST_FILL_FALLBACK)
#undef TOYHOST_FILL_FALLBACK
    if (realTime) s.fps.reset();
    if (!o.frames) o.frames = o.interactive ? 0 : defaults::kFrames;
    if (!o.captureEvery) o.captureEvery = defaults::kCaptureEvery;
    if (!o.pngLevel) o.pngLevel = defaults::kPngLevel;
    if (!o.captureMemoryBytes) o.captureMemoryBytes = defaults::kCaptureMemoryMiB << 20;
    return o;
}

SessionOptions withManifestDefaults(SessionOptions o, const RunDefaults& manifest) {
    SessionSettings& s = o.settings;
    if (!s.width && !s.height && manifest.width && manifest.height) {
        s.width = manifest.width;
        s.height = manifest.height;
    }
    // A window runs in real time until it is closed unless the command line says otherwise.
    if (!o.interactive) {
        if (!s.fps) s.fps = manifest.fps;
        if (!o.frames) o.frames = manifest.frames;
    }
    return o;
}

// --resume: the clock, date and canvas come from the checkpoint unless given, and must then agree.
Result<SessionOptions> withCheckpointSettings(SessionOptions o, const Checkpoint& c, std::optional<double>& wallClock) {
    SessionSettings& s = o.settings;
    const std::string file = o.resume->string();
    auto differs = [&](const std::string& option, const std::string& value) {
        return fileError(file, "the checkpoint was made with " + option + " " + value +
                                   "; resume with the same (or leave the option out)",
                         Code::UsageResume);
    };
    if (s.width && (*s.width != c.state.width || *s.height != c.state.height))
        return differs("--size", std::to_string(c.state.width) + "x" + std::to_string(c.state.height));
    if (s.fps && *s.fps != c.fps) return differs("--fps", std::to_string(c.fps));
    if (s.startTime != 0 && s.startTime != c.startTime) return differs("--start-time", std::to_string(c.startTime));
    if (wallClock && *wallClock != c.wallClock) return differs("--date", "(another date)");
    s.width = c.state.width;
    s.height = c.state.height;
    s.fps = c.fps;
    s.startTime = c.startTime;
    wallClock = c.wallClock;
    return o;
}

namespace {
// `toyhost sound --out`: an audio file by its extension, "-" for WAV on stdout, or a device.
Status checkSoundRequest(const SoundRequest& sound) {
    if (Status seconds = checkSoundSecondsSetting(sound.seconds); !seconds) return seconds;
    if (Status out = checkSoundOutput(sound.out); !out) return out;
    std::error_code ec;
    if (fs::is_directory(sound.out, ec)) return usage("--out " + sound.out.string() + ": is a folder; give a file name");
    std::string extension = sound.out.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!extension.empty() && extension != ".wav" && !findExecutable("ffmpeg"))
        return Error("--out " + sound.out.string() + ": " + extension.substr(1) +
                         " audio needs ffmpeg, which is not in PATH (Debian: apt-get install ffmpeg), or write a .wav",
                     Code::SoundFfmpegMissing);
    return okStatus();
}
}  // namespace

namespace {
// A canvas drawn in tiles (session/TiledStill.h): up to kMaxTiledCanvasSide a side, tiles from
// kMinTileSide to kMaxCanvasSide, and only without buffers, whose targets are the whole canvas.
Status checkTiledSize(int width, int height, std::optional<int> tile, const ManifestDesc& manifest, bool interactive,
                      bool framesInMemory) {
    using namespace defaults;
    if (tile && (*tile < kMinTileSide || *tile > kMaxCanvasSide))
        return settingError("tile", "must be " + std::to_string(kMinTileSide) + " to " + std::to_string(kMaxCanvasSide) +
                                        " pixels, got " + std::to_string(*tile));
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width < 1 || height < 1 || width > kMaxTiledCanvasSide || height > kMaxTiledCanvasSide)
        return settingError("size", "canvas size " + size + " is not between 1x1 and " +
                                        std::to_string(kMaxTiledCanvasSide) + "x" + std::to_string(kMaxTiledCanvasSide),
                            Code::UsageSize);
    const std::string why = tile ? "a tiled canvas (--tile)" : "canvas size " + size + " (more than " +
                                                                   std::to_string(kMaxCanvasSide) + " a side: drawn in tiles)";
    if (manifest.hasBuffers())
        return settingError(tile ? "tile" : "size",
                            why + ": this shadertoy has buffers, and a buffer is the size of the whole canvas, so it "
                                  "cannot be drawn in tiles; at most " + std::to_string(kMaxCanvasSide) + "x" +
                                  std::to_string(kMaxCanvasSide) + " for it",
                            Code::UsageSize);
    if (interactive) return settingError(tile ? "tile" : "size", why + ": a window cannot show it; run it headless", Code::UsageSize);
    // A frame read in memory is one target: its tiles are drawn into files only (once a defect: a
    // library Session of 20000x100 silently drew and handed over one 1024-wide tile, and compare
    // said "equal" for frames that differed beyond it).
    if (framesInMemory)
        return settingError(tile ? "tile" : "size",
                            why + ": only toyhost run draws a canvas in tiles, into PNG or EXR files; frames read in "
                                  "memory (the library's Session, Python, toyhost compare) are at most " +
                                std::to_string(kMaxCanvasSide) + "x" + std::to_string(kMaxCanvasSide),
                            Code::UsageSize);
    return okStatus();
}
}  // namespace

TimelineDesc timelineOf(const SessionPlan& plan) {
    const SessionSettings& s = plan.options.settings;
    return {s.fps.value_or(defaults::kFps), s.startTime, plan.wallClock.value_or(0.0), plan.mouse, plan.keys};
}

Result<OutputPattern> checkedOutput(const SessionOptions& o, int first, int end) {
    const SessionSettings& s = o.settings;
    Result<OutputPattern> pattern = OutputPattern::parse(*o.outPattern);
    if (!pattern) return pattern.error();
    if (!pattern->numbered() && !pattern->streamed() && countCaptured(first, end, *o.frames, *o.captureEvery) > 1)
        return usage("--out " + *o.outPattern + ": more than one frame is captured, so the "
                     "pattern needs a frame number placeholder such as %04d");
    if (pattern->kind().toFile) {
        const std::string name = pattern->pathFor(end - 1).filename().string();
        if (name.size() > 255)
            return usage("--out " + *o.outPattern + ": the file name is " + std::to_string(name.size()) +
                         " bytes long, more than the 255 a file system allows");
    }
    // A video has one frame rate; a window in real time renders at whatever rate it manages,
    // so its recording would play at the wrong speed: ask for the step it should have.
    if (pattern->kind().fixedRate && o.interactive && !s.fps)
        return usage("--out " + *o.outPattern + ": a video recorded from a window needs --fps (each frame then "
                     "advances iTime by exactly 1/fps, and the video plays at that rate); image files need none");
    if (pattern->kind().ffmpeg && !findExecutable("ffmpeg"))
        return Error("--out " + *o.outPattern + ": " + pattern->kind().name + " needs ffmpeg, which is not in PATH "
                     "(Debian: apt-get install ffmpeg)",
                     Code::CaptureFfmpeg);
    return std::move(*pattern);
}

Result<SessionPlan> planRecording(const SessionPlan& session, const std::string& out, int frames, int every, PassId pass) {
    if (frames < 1) return settingError("frames", "must be at least 1");
    if (every < 1) return settingError("every", "must be at least 1");
    SessionPlan recording;
    recording.options = session.options;
    SessionOptions& o = recording.options;
    o.outPattern = out;
    o.frames = frames;
    o.captureEvery = every;
    o.capturePass = pass;
    o.interactive = false;
    recording.first = 0;
    recording.end = frames;
    recording.wallClock = session.wallClock;
    recording.sampling = session.sampling;
    Result<OutputPattern> pattern = checkedOutput(o, 0, frames);
    if (!pattern) return pattern.error();
    if (!pattern->kind().toFile)
        return settingError("out", "a recording is written to files (frames or a video), not to stdout");
    recording.output = std::move(*pattern);
    if (recording.output->kind().ffmpeg && o.video.codec == "auto")
        (void)chooseAutoVideoEncoder(recording.output->extension());
    return recording;
}

namespace {

// prepareSession's parts, in the order it runs them; each fills its part of `run` (whose options
// are final) or says why it cannot.

// The frames: --frame-range, --shard and a --resume checkpoint's place.
Status planFrames(SessionPlan& run, const ManifestDesc& manifest, std::optional<Checkpoint> resume) {
    const SessionOptions& o = run.options;
    if (o.frameRange) {
        const auto [first, end] = *o.frameRange;
        if (first < 0 || end <= first || end > *o.frames)
            return usage("--frame-range " + std::to_string(first) + ":" + std::to_string(end) +
                         ": expected A:B with 0 <= A < B <= --frames (" + std::to_string(*o.frames) + ")");
        run.first = first;
        run.end = end;
    }
    if (o.shard) {
        const auto [index, count] = *o.shard;
        Result<FrameSpan> span = shardSpan(*o.frames, count, index);
        if (!span)
            return usage("--shard " + std::to_string(index) + "/" + std::to_string(count) +
                         ": expected i/n with 0 <= i < n <= --frames (" + std::to_string(*o.frames) + ")");
        run.first = span->first;
        run.end = span->end;
    }
    if (resume) {
        // Without a range, a resumed run renders from the checkpoint's frame on.
        if (!o.frameRange && !o.shard) run.first = std::min(resume->state.frame, run.end);
        if (resume->state.frame > run.first)
            return fileError(o.resume->string(),
                             "the checkpoint is at frame " + std::to_string(resume->state.frame) +
                                 ", after the first frame this run must render (" + std::to_string(run.first) + ")",
                             Code::UsageResume);
        if (resume->shadertoy != manifest.name || resume->codeHash != codeHash(manifest, run.defines))
            return fileError(o.resume->string(),
                             "the checkpoint was made from other code (shadertoy \"" + resume->shadertoy +
                                 "\"): a resumed run would not continue the same frames",
                             Code::CheckpointMismatch);
        if (resume->media != channelMedia(manifest))
            return fileError(o.resume->string(), "the checkpoint was made with other channel inputs", Code::CheckpointMismatch);
        run.resume = std::move(resume);
    }
    return okStatus();
}

// The output: --out's pattern, a tiled canvas's, and the options that apply to one kind only.
Status planOutput(SessionPlan& run, bool tiled) {
    const SessionOptions& o = run.options;
    if (o.outPattern) {
        Result<OutputPattern> pattern = checkedOutput(o, run.first, run.end);
        if (!pattern) return pattern.error();
        run.output = std::move(*pattern);
    }
    if (tiled) {
        if (run.output && !run.output->kind().tiles)
            return settingError("size", "a tiled canvas is written as " + tiledKindNames() + " files, not " +
                                            std::string(run.output->streamed() ? "a stream or video" : "this format"));
        if (o.capturePass != PassId::Image) return settingError("size", "a tiled canvas captures the Image pass only");
        run.tile = o.tile.value_or(defaults::kTileSide);
    }
    const bool exrAsked = o.exr.half || o.exr.compression != ExrCompression::None;
    if (exrAsked && (!run.output || !run.output->kind().exrSettings))
        return usage("--exr-compression and --exr-half apply only to an EXR --out (frame_%04d.exr)");
    if ((o.video.codec || o.video.quality || o.video.preset) && (!run.output || !run.output->kind().ffmpeg))
        return usage("--codec, --video-quality and --video-preset apply only to a video --out (" +
                     extensionsWhere(&OutputKind::ffmpeg) + ")");
    return okStatus();
}

// The timeline's input: a held --mouse, the mouse and key scripts.
Status planInput(SessionPlan& run) {
    const SessionOptions& o = run.options;
    const SessionSettings& s = o.settings;
    if (o.mouse) run.mouse = mouseHeldAt(o.mouse->x, o.mouse->y);
    if (s.mouseScript) {
        Result<std::string> text = readTextFile(*s.mouseScript);
        if (!text) return text.error();
        Result<MouseScript> script = parseMouseScript(*text, s.mouseScript->string());
        if (!script) return script.error();
        run.mouse = std::move(*script);
    }
    if (s.keyScript) {
        Result<std::string> text = readTextFile(*s.keyScript);
        if (!text) return text.error();
        Result<KeyScript> script = parseKeyScript(*text, s.keyScript->string());
        if (!script) return script.error();
        run.keys = std::move(*script);
    }
    return okStatus();
}

// The media: every image decoded and every video and audio source opened (planPlayer), and the
// video encoder --codec auto picks.
Status planMedia(SessionPlan& run, ManifestDesc manifest) {
    const SessionOptions& o = run.options;
    Result<PlayerPlan> plan = planPlayer(std::move(manifest), run.media, run.defines);
    if (!plan) return plan.error();
    run.shadertoy = std::move(*plan);
    // --codec auto tries the hardware encoders with short ffmpeg runs; the choice is kept for the
    // process, so made here, off the GL thread, the recorder (made on it) finds it ready.
    if (run.output && run.output->kind().ffmpeg && o.video.codec == "auto")
        (void)chooseAutoVideoEncoder(run.output->extension());
    return okStatus();
}

}  // namespace

Result<SessionPlan> prepareSession(const SessionOptions& asked) {
    SessionOptions options = asked;
    if (!options.startedAt) options.startedAt = std::chrono::steady_clock::now();
    if (options.sound) {
        if (Status sound = checkSoundRequest(*options.sound); !sound) return sound.error();
        if (options.outPattern) return usage("a sound session writes audio, not frames (no --out pattern)");
    }
    if (options.frames)
        if (Status frames = checkFramesSetting(*options.frames); !frames) return frames.error();
    if (options.settings.width.has_value() != options.settings.height.has_value())
        return settingError("size", "give both width and height, or neither (the default)");
    // The date, parsed once: iDate at frame 0.
    std::optional<double> wallClock;
    if (options.settings.date) {
        Result<double> parsed = parseWallClock(*options.settings.date);
        if (!parsed) return settingError("date", parsed.error().first().message);
        wallClock = *parsed;
    }
    if (options.checkpointEvery && *options.checkpointEvery < 1) return usage("--checkpoint-every must be at least 1");
    if (options.checkpointEvery && !options.checkpoint) return usage("--checkpoint-every needs --checkpoint FILE");
    if (options.frameRange && options.shard) return usage("--frame-range and --shard cannot be combined");
    if (options.interactive && (options.checkpoint || options.resume || options.frameRange || options.shard))
        return usage("--checkpoint, --resume, --frame-range and --shard are for headless runs");
    if (options.watch && (options.checkpoint || options.resume || options.frameRange || options.shard))
        return usage("--checkpoint, --resume, --frame-range and --shard cannot be combined with --watch");
    Result<ManifestDesc> manifest = options.shadertoy ? Result<ManifestDesc>(*options.shadertoy) : loadShadertoy(options.target);
    if (!manifest) return manifest.error();
    if (options.shadertoy && options.watch) return usage("--watch needs the shadertoy's files, not a loaded shadertoy");
    if (options.sound && !manifest->sound)
        return fileError(manifest->manifestPath.string(), "the shadertoy has no Sound pass (mainSound)", Code::SoundMissing);
    std::optional<Checkpoint> resume;
    SessionOptions given = withManifestDefaults(options, manifest->runDefaults);
    if (options.resume) {
        Result<Checkpoint> read = readCheckpoint(*options.resume);
        if (!read) return read.error();
        Result<SessionOptions> merged = withCheckpointSettings(std::move(given), *read, wallClock);
        if (!merged) return merged.error();
        given = std::move(*merged);
        resume = std::move(*read);
    }
    if (Status shutter = checkShutterGiven(options.settings, given.settings); !shutter) return shutter.error();
    SessionOptions o = withDefaults(std::move(given));
    const SessionSettings& s = o.settings;
    // A headless run's iDate is the wall clock at frame 0 unless --date (or a checkpoint) says
    // otherwise; a window shows the live date.
    if (!o.interactive && !wallClock) wallClock = localWallClockNow();
    const bool tiled = o.tile || *s.width > defaults::kMaxCanvasSide || *s.height > defaults::kMaxCanvasSide;
    if (tiled)
        if (Status size = checkTiledSize(*s.width, *s.height, o.tile, *manifest, o.interactive, o.framesInMemory); !size)
            return size.error();
    // Every setting's check (the validation table of toyhost/Settings.h's list).
    if (Status checked = checkSessionSettings(s, SettingContext{tiled}); !checked) return checked.error();
    if (o.checkpoint) {
        std::error_code ec;
        if (fs::is_directory(*o.checkpoint, ec))
            return usage("--checkpoint " + o.checkpoint->string() + ": is a folder; give a file name");
    }
    if (o.mouse)
        if (Status mouse = checkMouseSetting(o.mouse->x, o.mouse->y); !mouse) return mouse.error();
    SamplingDesc sampling{*s.supersample, *s.motionBlur, *s.shutterDegrees, s.dither};
    if (s.shutterOffset) sampling.shutterOffset = *parseShutterOffset(*s.shutterOffset);  // checked above
    if (s.sampleSpace) sampling.linear = *parseSampleSpaceLinear(*s.sampleSpace);
    if (*o.captureEvery < 1) return usage("--capture-every must be at least 1");
    if (*o.captureMemoryBytes == 0) return usage("--capture-memory must be at least 1 (MiB)");
    if (o.mouse && s.mouseScript) return usage("--mouse and --mouse-script cannot be combined");
    if (*o.pngLevel < 0 || *o.pngLevel > 9) return usage("--png-level must be 0..9");
    if (o.encoderThreads < 0 || o.encoderThreads > 1024) return usage("--encoder-threads must be 0 (automatic) to 1024");
    if (o.video.quality && (*o.video.quality < 0 || *o.video.quality > 63))
        return usage("--video-quality must be 0..63 (a constant rate factor; lower is better)");

    if (!manifest->find(o.capturePass))
        return usage(std::string("--capture-pass ") + passName(o.capturePass) + ": " +
                     manifest->manifestPath.string() + " has no such pass");

    SessionPlan run{o, {}, std::nullopt, {}, {}, 0, *o.frames, std::nullopt, wallClock,
                    MediaOptions{s.mediaFiles, s.mediaFolders, o.webcam, o.mic}, sampling};
    Result<MacroDefines> defines = parseMacroDefines(s.defines);
    if (!defines) return defines.error();
    run.defines = std::move(*defines);
    if (Status planned = planFrames(run, *manifest, std::move(resume)); !planned) return planned.error();
    if (Status planned = planOutput(run, tiled); !planned) return planned.error();
    if (Status planned = planInput(run); !planned) return planned.error();
    if (Status planned = planMedia(run, std::move(*manifest)); !planned) return planned.error();
    return run;
}

}  // namespace toyhost
