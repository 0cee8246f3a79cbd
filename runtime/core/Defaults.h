// Defaults: every default value of a run. The ones a library user sees are written once, in the
// public list (toyhost/Defaults.h), and named here after it; the engine's own follow. Descriptions
// (PlayerDesc, SessionOptions) leave a field at zero/absent to mean "the default", and one function
// per description (withDefaults) fills them from here; the CLI shows these same numbers in --help.
// No GL needed.
#pragma once

#include <cstddef>

#include <toyhost/Defaults.h>

namespace toyhost::defaults {

// The public list's values (toyhost/Defaults.h).
inline constexpr Defaults kPublic{};

inline constexpr int kCanvasWidth = kPublic.width;
inline constexpr int kCanvasHeight = kPublic.height;
inline constexpr int kFrames = kPublic.frames;
inline constexpr double kFps = kPublic.fps;             // fixed time step: iTime = start + n / fps
inline constexpr int kPngLevel = kPublic.pngLevel;              // --png-level of captured PNG files (fastest compression)
inline constexpr std::size_t kCaptureMemoryMiB = kPublic.captureMemoryMiB;  // frames waiting for the encoders
inline constexpr int kCaptureEvery = kPublic.captureEvery;
inline constexpr int kMaxCanvasSide = kPublic.maxCanvasSide;     // --size limit, before asking GL for its own
// Better pixels than the site (timing/SamplePattern.h): one sample per pixel at one instant unless
// asked; a shutter of 180 degrees (open half the frame step) is the film convention.
inline constexpr int kSupersample = kPublic.supersample;
inline constexpr int kMotionBlurSamples = kPublic.motionBlur;
inline constexpr double kShutterDegrees = kPublic.shutterDegrees;
inline constexpr int kMaxSupersample = kPublic.maxSupersample;         // --supersample limit (256 samples per pixel)
inline constexpr int kMaxMotionBlurSamples = kPublic.maxMotionBlur;  // --motion-blur limit
inline constexpr int kMaxSamplesPerFrame = kPublic.maxSamplesPerFrame;   // supersample^2 x motion-blur samples
// A tiled still (session/TiledStill.h): tiles of this side unless --tile says, and the largest
// canvas side it takes (PNG and EXR hold more; two bands of rows stay in memory).
inline constexpr int kTileSide = 1024;
inline constexpr int kMinTileSide = 16;
inline constexpr int kMaxTiledCanvasSide = 65536;
// `toyhost compare`'s difference images: |a - b| times this per channel (a 1-level difference is
// dark but visible, 32 levels and more are white).
inline constexpr int kCompareDiffGain = 8;
// Frames `toyhost compare` renders when neither --frames nor a manifest's "defaults" say.
inline constexpr int kCompareFrames = kPublic.compareFrames;
// Numbers a user may give: beyond these a float uniform is no longer a usable number (iTime, iMouse
// become Inf or lose every fraction), so they are usage errors, not silent Inf in the shader.
inline constexpr double kMinFps = kPublic.minFps;
inline constexpr double kMaxFps = kPublic.maxFps;
inline constexpr double kMaxSeconds = 1e9;          // --start-time, script "time"
inline constexpr double kMaxPixelCoordinate = 1e6;  // --mouse, script "x"/"y"
// iTimeDelta the site uses on the frame after a restart and while paused (1/60 s).
inline constexpr double kRestartTimeDelta = 1.0 / 60.0;
inline constexpr double kSampleRate = kPublic.sampleRate;   // iSampleRate in every pass
// Cube A: six square faces of this side (the site's), RGBA16F.
inline constexpr int kCubeBufferSize = 1024;
// Stand-ins for inputs toyhost does not have: stock cubemap faces of unknown size, videos
// (a moving pattern), and the volume side when the table does not know it.
inline constexpr int kCubemapStandInSize = 256;
inline constexpr int kVideoStandInWidth = 640;
inline constexpr int kVideoStandInHeight = 360;
inline constexpr int kVolumeStandInSize = 32;
// Videos are decoded ahead of the frame shown on their own thread: at most this many frames
// wait in the queue, and no more than this many bytes of them (one 4K frame is 33 MB).
inline constexpr int kVideoAheadFrames = 3;
inline constexpr std::size_t kVideoAheadBytes = std::size_t(96) << 20;
// Validating a manifest collects this many problems, then stops looking ("stopped after 50
// problems"): a file of millions of bad entries costs no more than parsing it (4 million bad "media"
// entries took 210 s and 5.5 GB). Below the 100 lines the CLI prints, so the note shows too.
inline constexpr std::size_t kMaxManifestProblems = 50;
// Decoding one image file (image/DecodeLimits.h). A progressive JPEG makes the decoder pass over
// every block of a component once per scan, and a scan can be a dozen bytes: a 330 KB file of
// 20000 scans kept libjpeg busy for minutes. Encoders write 10 scans (libjpeg's progression) to a
// few dozen; 500 is the limit libjpeg-turbo's own fuzz targets set (TJPARAM_SCANLIMIT, djpeg
// -maxscans). Whatever else makes a decode slow, it stops after kImageDecodeSeconds of the decoding thread's
// CPU time (waiting for a core on a loaded machine or a suspension does not count): far beyond
// the few seconds the largest texture (16384x16384) takes.
inline constexpr int kMaxJpegScans = 500;
inline constexpr double kImageDecodeSeconds = 30.0;
// The Sound pass: the site renders 180 s, in blocks of 512x512 samples.
inline constexpr double kSoundSeconds = kPublic.soundSeconds;
inline constexpr double kMaxSoundSeconds = 3600.0;  // `toyhost sound --seconds` limit
inline constexpr int kSoundBlockSide = 512;
// The watchdog (headless runs; a window has no frame limit): a frame whose passes take longer
// than this ends the run (--frame-timeout), and so does a pass that takes longer to compile
// (--compile-timeout). 0 turns either off.
inline constexpr double kFrameTimeoutSeconds = kPublic.frameTimeoutSeconds;
inline constexpr double kCompileTimeoutSeconds = kPublic.compileTimeoutSeconds;
// A library Session (toyhost/Session.h) has neither limit unless its settings give one.
inline constexpr double kSessionTimeoutSeconds = 0.0;
// A limit other than 0 (off) is at least 0.1 s: shorter limits measure the watchdog's own polling
// and thread start-up rather than the shader (and were reported as "0.0 s, longer than 0.0").
inline constexpr double kMinTimeoutSeconds = 0.1;
inline constexpr double kMaxTimeoutSeconds = 1e6;
// After Ctrl-C or SIGTERM the run stops before its next frame; when the render thread is stuck
// in GL (a long draw, a stalled encoder) for longer than this, toyhost removes its unfinished
// files, stops its child processes and exits anyway.
inline constexpr double kStopGraceSeconds = 3.0;
// The watchdog's limits count the time the process runs: a gap of more than this between two of
// its 50 ms ticks is a suspension (SIGSTOP, Ctrl-Z, a scheduler's suspend, a machine's sleep), and
// does not count. Under load a thread waits for a core for tens of milliseconds, not seconds.
inline constexpr double kSuspensionGapSeconds = 1.0;
// A pass's source with bytes GL must not see (NUL, non-ASCII outside comments) lists the first this
// many with their line and column, then says how many more there are (a binary file has millions;
// the list of all errors printed is itself capped at 100, so every pass's count is seen).
inline constexpr std::size_t kMaxShaderTextProblems = 20;
// A JSON file's keys that appear twice in one object: the first this many are listed with their
// place, then one line counts the rest.
inline constexpr std::size_t kMaxListedDuplicateKeys = 20;

}  // namespace toyhost::defaults
