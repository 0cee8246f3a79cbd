// SessionOptions: what a user asks of a session (`toyhost run`, `toyhost sound`, a program that
// embeds toyhost): the library's own SessionSettings, embedded, plus what only the commands have
// (frames, capture, checkpoints, shards, a window). Absent fields mean "the default" (withDefaults
// fills them from core/Defaults.h; a value the user gave, such as --frames 0, is kept so that
// prepareSession can refuse it), and the checks that need no GL (prepareSession: the manifest,
// images and media, output pattern, input scripts, ffmpeg), shared by every driver. No GL needed.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <toyhost/Settings.h>

#include "capture/OutputPattern.h"
#include "capture/VideoSink.h"
#include "image/ImageWriters.h"
#include "core/Result.h"
#include "gl/HeadlessContext.h"
#include "input/InputScript.h"
#include "manifest/ManifestDesc.h"
#include "media/ChannelMedia.h"
#include "player/PlayerDesc.h"
#include "session/Checkpoint.h"
#include "timing/SamplePattern.h"
#include "timing/Timeline.h"

namespace toyhost {

// `toyhost sound`: the Sound pass rendered to an audio file instead of frames.
struct SoundRequest {
    std::filesystem::path out;             // .wav, or .flac/.ogg/.opus/.mp3/.m4a through ffmpeg; "-": WAV on stdout
    double seconds = defaults::kSoundSeconds;  // more than 0 (the site's 180 s by default)
};

struct SessionOptions {
    std::filesystem::path target;          // folder with manifest.json, the manifest file, or an export
    // A shadertoy already loaded (the library API's Shadertoy, an export given as text): used instead
    // of loading `target`, which then only names it.
    std::shared_ptr<const ManifestDesc> shadertoy;
    // When the command started, for the report's start-up time; default: when prepareSession ran.
    std::optional<std::chrono::steady_clock::time_point> startedAt;
    // Canvas, clock, date, media, scripts, Image format and watchdog limits: the settings a library
    // Session takes, as given. Absent: the manifest's defaults, else core/Defaults.h; in a window,
    // no fps means real time and no frame timeout. The limits are enforced by the session's
    // Watchdog (session/Watchdog.h), when it has one.
    SessionSettings settings;
    // Window mode: no frame count means "until the window closes" and no fps means real time.
    bool interactive = false;
    // The caller reads the frames from memory (the library's Session: Python, toyhost compare):
    // the canvas is one GL target, never drawn in tiles, so at most defaults::kMaxCanvasSide a side.
    bool framesInMemory = false;
    // Re-render (headless) or hot-reload (window) when a file of the shadertoy changes.
    bool watch = false;
    // Window with a fixed step (fps): draw frames as fast as the display allows instead of fps
    // frames per second of wall time (timing/FramePacer.h).
    bool unpaced = false;
    // Headless: draw fps frames per second of wall time (a live stream's rate) instead of as fast as
    // the machine can; the frames are the same.
    bool paced = false;
    std::optional<int> frames;             // default defaults::kFrames (headless), no end (window)
    std::optional<std::string> outPattern;
    std::optional<int> captureEvery;       // default defaults::kCaptureEvery
    PassId capturePass = PassId::Image;
    std::optional<glm::vec2> mouse;        // --mouse X,Y: pressed on frame 0 and held
    std::string webcam;                    // --webcam, --mic: MediaOptions' live sources
    std::string mic;
    EglPlatform eglPlatform = EglPlatform::Automatic;

    // Capture pipeline (runtime/capture).
    std::optional<int> pngLevel;           // --png-level 0..9; default defaults::kPngLevel
    ExrSettings exr;                       // --exr-compression, --exr-half (default: exact 32-bit, uncompressed)
    bool syncCapture = false;              // read back and encode on the render thread (reference path)
    int encoderThreads = 0;                // 0: defaultEncoderThreads()
    std::optional<std::size_t> captureMemoryBytes;  // cap on frames waiting for encoders
    VideoSettings video;                   // codec and quality of --out x.mp4|.webm|.mov|.mkv
    int rawStreamFd = 1;                   // where --out - writes
    // glFinish after every frame. For benchmarks: llvmpipe drops queued work that a later draw
    // fully overwrites before anything reads it, so an unsynchronised render-only loop does not
    // measure the shading cost.
    bool finishEachFrame = false;
    // Read every buffer back after every frame and report the first NaN/Inf (costs a readback per
    // buffer and frame). Without it, buffers are checked at the end of the run and on captured
    // float frames.
    bool checkFinite = false;
    // --tile SIDE: Image drawn in tiles of at most SIDE x SIDE (session/TiledStill.h). A canvas
    // wider or taller than defaults::kMaxCanvasSide is tiled without it (default tile side
    // defaults::kTileSide); only shadertoys without buffers.
    std::optional<int> tile;
    // Render only the Sound pass, to this file (no frames, no Player).
    std::optional<SoundRequest> sound;

    // Long runs (headless only). --checkpoint FILE: the full state is written to FILE (atomically)
    // every `checkpointEvery` frames, when the run is interrupted and when it ends; --resume FILE
    // continues from such a file with byte-identical frames.
    std::optional<std::filesystem::path> checkpoint;
    std::optional<int> checkpointEvery;
    std::optional<std::filesystem::path> resume;
    // Render farms: only frames [first, end) of the run are captured (--frame-range A:B), or
    // shard i of n (--shard i/n: the frames split into n contiguous ranges, i from 0). Frames
    // before the range are simulated (buffers run, nothing is captured; a shadertoy without
    // buffers skips them), so the union of the ranges equals the whole run byte for byte.
    std::optional<std::pair<int, int>> frameRange;
    std::optional<std::pair<int, int>> shard;
};

// `options` with every absent field set to its default (frames 0 then means "no end"; an
// interactive run keeps fps absent: real time).
SessionOptions withDefaults(SessionOptions options);

// `options` with each setting the user left absent taken from the manifest's "defaults" (size
// always; fps and frames only for headless runs: a window runs in real time until closed).
SessionOptions withManifestDefaults(SessionOptions options, const RunDefaults& manifest);

// Everything a run needs that can be checked without GL.
struct SessionPlan {
    SessionOptions options;                    // with defaults applied
    PlayerPlan shadertoy;                  // the shadertoy, planned (graph, decoded images, media)
    std::optional<OutputPattern> output;
    MouseScript mouse;
    KeyScript keys;
    int first = 0;                         // frames [first, end) are captured (the frame range)
    int end = 0;
    std::optional<Checkpoint> resume;      // --resume: the state the run continues from
    // iDate at frame 0 (FrameClock form): settings.date parsed, the checkpoint's, or now (headless);
    // absent in a window without a date: it shows the live date.
    std::optional<double> wallClock;
    MediaOptions media;                    // settings' media folders and files, --webcam, --mic
    // settings' supersample, motion blur, shutter and dither with the defaults filled in.
    SamplingDesc sampling;
    int tile = 0;                          // a tiled still: the tile side; 0: not tiled
    MacroDefines defines = {};             // settings' defines, parsed: in every pass
};

// The run's fixed-step input (timing/Timeline.h): its clock, date and input scripts.
TimelineDesc timelineOf(const SessionPlan& plan);

// The output `o.outPattern` names (checked as --out is) for frames [first, end) captured every
// o.captureEvery of o.frames: a numbered pattern when more than one is captured, a file name a file
// system takes, ffmpeg for a video.
Result<OutputPattern> checkedOutput(const SessionOptions& o, int first, int end);

// A recording of the next `frames` frames of a running session (the library's Session::record):
// `session`'s options with the output `out`, `frames`, capture-every `every` and `pass`, frames
// numbered from 0 as a run's; checked as a run's --out is (a stream to stdout is refused). No GL.
Result<SessionPlan> planRecording(const SessionPlan& session, const std::string& out, int frames, int every, PassId pass);

// Validates `options` (after withDefaults), loads the shadertoy and decodes its images, parses
// the output pattern and the input scripts. No GL.
Result<SessionPlan> prepareSession(const SessionOptions& options);

}  // namespace toyhost
