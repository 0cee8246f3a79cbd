// toyhost/DiagnosticCode.h (public API, stable): every kind of problem or notice toyhost reports, as
// an enum with its short stable text (printed in brackets, for scripts and tests) and its
// category. Exit codes and control flow follow the category (usage errors exit 2, interruptions
// 128 + signal, the watchdog 124), never the text. New codes may be added; texts do not change.
// Every enumerator's number is written out: programs compiled against an older header keep their
// numbers. A new code takes the next number after the highest one, wherever its line is listed;
// a number is never reused, not even after its code is removed (tests/unit/test_diagnostics.cpp
// pins them all). No GL needed.
#pragma once

#include <cstdint>
#include <string_view>

#include <toyhost/Export.h>

namespace toyhost {

// What kind of problem a code is; decides exit codes and what a run does next.
// Numbered like the codes: written out, never changed or reused.
enum class Category : std::uint8_t {
    Usage = 0,        // the command line (or an API call's arguments): exit 2
    Input = 1,        // the user's files: manifest, export, scripts, images, media, checkpoints
    Shader = 2,       // a pass does not compile or link
    Output = 3,       // writing results: files, encoders, stdout
    Gl = 4,           // the GL driver, EGL or the window system
    Interrupted = 5,  // a stop was asked for (SIGINT / SIGTERM / SessionCore::requestStop)
    Watchdog = 6,     // a time limit ended the run
    Internal = 7,     // a bug in toyhost
    Report = 8,       // not a problem: notices and warnings about a run that goes on
};

// X(enumerator, number, text, category). Listed by text; the numbers are the enumerators' values
// (the order of the list means nothing).
#define TOYHOST_DIAGNOSTIC_CODES(X) \
    X(AudioDecode,              0, "audio.decode",              Input) \
    X(AudioFfmpegMissing,       1, "audio.ffmpeg-missing",      Input) \
    X(AudioLive,                2, "audio.live",                Input) \
    X(AudioSettings,            3, "audio.settings",            Input) \
    X(AudioTooLong,             4, "audio.too-long",            Input) \
    X(BufferNonFinite,          5, "buffer.non-finite",         Report) \
    X(Cancelled,                6, "cancelled",                 Interrupted) \
    X(CaptureDropped,           7, "capture.dropped",           Report) \
    X(CaptureException,         8, "capture.exception",         Output) \
    X(CaptureFfmpeg,            9, "capture.ffmpeg",            Output) \
    X(CaptureFormat,           10, "capture.format",            Output) \
    X(CaptureReadback,         11, "capture.readback",          Output) \
    X(CaptureSize,             12, "capture.size",              Output) \
    X(CaptureStopped,          13, "capture.stopped",           Output) \
    X(CaptureWav,              14, "capture.wav",               Output) \
    X(ChannelFilter,          115, "channel.filter",            Report) \
    X(ChannelUnbound,          15, "channel.unbound",           Report) \
    X(CheckpointFormat,        16, "checkpoint.format",         Input) \
    X(CheckpointMismatch,      17, "checkpoint.mismatch",       Input) \
    X(CubemapFaceSize,         18, "cubemap.face-size",         Input) \
    X(CubemapLayout,           19, "cubemap.layout",            Input) \
    X(Unclassified,            20, "error",                     Internal) \
    X(ExportDuplicate,         21, "export.duplicate",          Input) \
    X(ExportJson,              22, "export.json",               Input) \
    X(ExportMissing,           23, "export.missing",            Input) \
    X(ExportMissingBuffer,     24, "export.missing-buffer",     Input) \
    X(ExportShape,             25, "export.shape",              Input) \
    X(ExportType,              26, "export.type",               Input) \
    X(ExportUnsupportedInput,  27, "export.unsupported-input",  Input) \
    X(ExportValue,             28, "export.value",              Input) \
    X(GlEgl,                   29, "gl.egl",                    Gl) \
    X(GlFeature,               30, "gl.feature",                Gl) \
    X(GlReadback,              31, "gl.readback",               Gl) \
    X(GlSetup,                 32, "gl.setup",                  Gl) \
    X(GlSound,                 33, "gl.sound",                  Gl) \
    X(GlTexture,               34, "gl.texture",                Gl) \
    X(GlTextureSize,           35, "gl.texture-size",           Gl) \
    X(ImageDecode,             36, "image.decode",              Input) \
    X(ImagePngLevel,           37, "image.png-level",           Internal) \
    X(ImageSize,               38, "image.size",                Input) \
    X(ImageTooLarge,           39, "image.too-large",           Input) \
    X(InspectRegion,           40, "inspect.region",            Input) \
    X(Internal,                41, "internal",                  Internal) \
    X(Interrupted,             42, "interrupted",               Interrupted) \
    X(IoBrokenPipe,            43, "io.broken-pipe",            Output) \
    X(IoExists,                44, "io.exists",                 Output) \
    X(IoLinkLoop,              45, "io.link-loop",              Input) \
    X(IoNoSpace,               46, "io.no-space",               Output) \
    X(IoNotAFile,              47, "io.not-a-file",             Input) \
    X(IoNotAFolder,            48, "io.not-a-folder",           Input) \
    X(IoNotFound,              49, "io.not-found",              Input) \
    X(IoRead,                  50, "io.read",                   Input) \
    X(IoTooLarge,              51, "io.too-large",              Input) \
    X(IoWrite,                 52, "io.write",                  Output) \
    X(JsonDuplicateKey,        53, "json.duplicate-key",        Input) \
    X(ManifestField,           54, "manifest.field",            Input) \
    X(ManifestJson,            55, "manifest.json",             Input) \
    X(ManifestMediaNearMiss,   56, "manifest.media-near-miss",  Input) \
    X(ManifestMissing,         57, "manifest.missing",          Input) \
    X(ManifestReference,       58, "manifest.reference",        Input) \
    X(ManifestType,            59, "manifest.type",             Input) \
    X(ManifestUnknownField,    60, "manifest.unknown-field",    Input) \
    X(ManifestUnknownPass,     61, "manifest.unknown-pass",     Input) \
    X(ManifestUnused,          62, "manifest.unused",           Report) \
    X(ManifestValue,           63, "manifest.value",            Input) \
    X(MediaNotFound,           64, "media.not-found",           Input) \
    X(MediaSizeMismatch,       65, "media.size-mismatch",       Report) \
    X(MediaSupplied,           66, "media.supplied",            Report) \
    X(MediaStandIn,            67, "media.stand-in",            Report) \
    X(MediaUnknownStandIn,     68, "media.unknown-stand-in",    Report) \
    X(Process,                 69, "process",                   Output) \
    X(ScriptEvent,             70, "script.event",              Input) \
    X(ScriptJson,              71, "script.json",               Input) \
    X(ScriptKey,               72, "script.key",                Input) \
    X(ShaderCompile,           73, "shader.compile",            Shader) \
    X(ShaderLink,              74, "shader.link",               Shader) \
    X(ShaderLoopCap,          116, "shader.loop-cap",           Report) \
    X(ShaderNonAscii,          75, "shader.non-ascii",          Shader) \
    X(ShaderNul,               76, "shader.nul",                Shader) \
    X(ShaderPreprocess,        77, "shader.preprocess",         Shader) \
    X(ShaderPreprocessed,      78, "shader.preprocessed",       Report) \
    X(ShaderRuleSkipped,      117, "shader.rule-skipped",       Report) \
    X(SoundChannel,            79, "sound.channel",             Input) \
    X(SoundEncode,             80, "sound.encode",              Output) \
    X(SoundFfmpegMissing,      81, "sound.ffmpeg-missing",      Output) \
    X(SoundMissing,            82, "sound.missing",             Input) \
    X(SoundSkipped,            83, "sound.skipped",             Report) \
    X(StateBuffers,            84, "state.buffers",             Input) \
    X(StateSize,               85, "state.size",                Input) \
    X(Usage,                   86, "usage",                     Usage) \
    X(UsageDate,               87, "usage.date",                Usage) \
    X(UsageOut,                88, "usage.out",                 Usage) \
    X(UsagePasses,             89, "usage.passes",              Usage) \
    X(UsageResume,             90, "usage.resume",              Usage) \
    X(UsageSize,               91, "usage.size",                Usage) \
    X(VideoDecode,             92, "video.decode",              Input) \
    X(VideoDevice,             93, "video.device",              Input) \
    X(VideoNoFfmpeg,           94, "video.no-ffmpeg",           Input) \
    X(VideoNoFrames,           95, "video.no-frames",           Input) \
    X(VideoNoStream,           96, "video.no-stream",           Input) \
    X(VideoProbe,              97, "video.probe",               Input) \
    X(VideoRate,               98, "video.rate",                Input) \
    X(VideoRead,               99, "video.read",                Input) \
    X(VideoSize,              100, "video.size",                Input) \
    X(VideoStillImage,        101, "video.still-image",         Report) \
    X(VolumeDecode,           102, "volume.decode",             Input) \
    X(WatchdogCompile,        103, "watchdog.compile",          Watchdog) \
    X(WatchdogFrame,          104, "watchdog.frame",            Watchdog) \
    X(WatchdogInput,          105, "watchdog.input",            Watchdog) \
    X(WatchdogOutput,         106, "watchdog.output",           Watchdog) \
    X(WatchChanged,           107, "watch.changed",             Report) \
    X(WindowCreate,           108, "window.create",             Gl) \
    X(WindowHelp,             109, "window.help",               Report) \
    X(WindowInit,             110, "window.init",               Gl) \
    X(WindowInspector,        114, "window.inspector",          Report) \
    X(WindowReload,           111, "window.reload",             Report) \
    X(WindowScreenshot,       112, "window.screenshot",         Report) \
    X(ManifestLoneShader,     113, "manifest.lone-shader",      Report)

enum class Code : std::uint16_t {
#define TOYHOST_CODE_ENUMERATOR(name, number, text, category) name = number,
    TOYHOST_DIAGNOSTIC_CODES(TOYHOST_CODE_ENUMERATOR)
#undef TOYHOST_CODE_ENUMERATOR
};

// The code's stable text ("manifest.value").
TOYHOST_API std::string_view codeName(Code code);
TOYHOST_API Category categoryOf(Code code);
// "usage", "input", "shader", ...
TOYHOST_API std::string_view categoryName(Category category);

}  // namespace toyhost
