// toyhost/DiagnosticCode.h (public API, stable): every kind of problem or notice toyhost reports, as
// an enum with its short stable text (printed in brackets, for scripts and tests) and its
// category. Exit codes and control flow follow the category (usage errors exit 2, interruptions
// 128 + signal, the watchdog 124), never the text. New codes may be added; texts do not change.
// No GL needed.
#pragma once

#include <cstdint>
#include <string_view>

#include <toyhost/Export.h>

namespace toyhost {

// What kind of problem a code is; decides exit codes and what a run does next.
enum class Category : std::uint8_t {
    Usage,        // the command line (or an API call's arguments): exit 2
    Input,        // the user's files: manifest, export, scripts, images, media, checkpoints
    Shader,       // a pass does not compile or link
    Output,       // writing results: files, encoders, stdout
    Gl,           // the GL driver, EGL or the window system
    Interrupted,  // a stop was asked for (SIGINT / SIGTERM / SessionCore::requestStop)
    Watchdog,     // a time limit ended the run
    Internal,     // a bug in toyhost
    Report,       // not a problem: notices and warnings about a run that goes on
};

// X(enumerator, text, category)
#define TOYHOST_DIAGNOSTIC_CODES(X) \
    X(AudioDecode,            "audio.decode",              Input) \
    X(AudioFfmpegMissing,     "audio.ffmpeg-missing",      Input) \
    X(AudioLive,              "audio.live",                Input) \
    X(AudioSettings,          "audio.settings",            Input) \
    X(AudioTooLong,           "audio.too-long",            Input) \
    X(BufferNonFinite,        "buffer.non-finite",         Report) \
    X(Cancelled,              "cancelled",                 Interrupted) \
    X(CaptureDropped,         "capture.dropped",           Report) \
    X(CaptureException,       "capture.exception",         Output) \
    X(CaptureFfmpeg,          "capture.ffmpeg",            Output) \
    X(CaptureFormat,          "capture.format",            Output) \
    X(CaptureReadback,        "capture.readback",          Output) \
    X(CaptureSize,            "capture.size",              Output) \
    X(CaptureStopped,         "capture.stopped",           Output) \
    X(CaptureWav,             "capture.wav",               Output) \
    X(ChannelUnbound,         "channel.unbound",           Report) \
    X(CheckpointFormat,       "checkpoint.format",         Input) \
    X(CheckpointMismatch,     "checkpoint.mismatch",       Input) \
    X(CubemapFaceSize,        "cubemap.face-size",         Input) \
    X(CubemapLayout,          "cubemap.layout",            Input) \
    X(Unclassified,           "error",                     Internal) \
    X(ExportDuplicate,        "export.duplicate",          Input) \
    X(ExportJson,             "export.json",               Input) \
    X(ExportMissing,          "export.missing",            Input) \
    X(ExportMissingBuffer,    "export.missing-buffer",     Input) \
    X(ExportShape,            "export.shape",              Input) \
    X(ExportType,             "export.type",               Input) \
    X(ExportUnsupportedInput, "export.unsupported-input",  Input) \
    X(ExportValue,            "export.value",              Input) \
    X(GlEgl,                  "gl.egl",                    Gl) \
    X(GlFeature,              "gl.feature",                Gl) \
    X(GlReadback,             "gl.readback",               Gl) \
    X(GlSetup,                "gl.setup",                  Gl) \
    X(GlSound,                "gl.sound",                  Gl) \
    X(GlTexture,              "gl.texture",                Gl) \
    X(GlTextureSize,          "gl.texture-size",           Gl) \
    X(ImageDecode,            "image.decode",              Input) \
    X(ImagePngLevel,          "image.png-level",           Internal) \
    X(ImageSize,              "image.size",                Input) \
    X(ImageTooLarge,          "image.too-large",           Input) \
    X(InspectRegion,          "inspect.region",            Input) \
    X(Internal,               "internal",                  Internal) \
    X(Interrupted,            "interrupted",               Interrupted) \
    X(IoBrokenPipe,           "io.broken-pipe",            Output) \
    X(IoExists,               "io.exists",                 Output) \
    X(IoLinkLoop,             "io.link-loop",              Input) \
    X(IoNoSpace,              "io.no-space",               Output) \
    X(IoNotAFile,             "io.not-a-file",             Input) \
    X(IoNotAFolder,           "io.not-a-folder",           Input) \
    X(IoNotFound,             "io.not-found",              Input) \
    X(IoRead,                 "io.read",                   Input) \
    X(IoTooLarge,             "io.too-large",              Input) \
    X(IoWrite,                "io.write",                  Output) \
    X(JsonDuplicateKey,       "json.duplicate-key",        Input) \
    X(ManifestField,          "manifest.field",            Input) \
    X(ManifestJson,           "manifest.json",             Input) \
    X(ManifestMediaNearMiss,  "manifest.media-near-miss",  Input) \
    X(ManifestMissing,        "manifest.missing",          Input) \
    X(ManifestReference,      "manifest.reference",        Input) \
    X(ManifestType,           "manifest.type",             Input) \
    X(ManifestUnknownField,   "manifest.unknown-field",    Input) \
    X(ManifestUnknownPass,    "manifest.unknown-pass",     Input) \
    X(ManifestUnused,         "manifest.unused",           Report) \
    X(ManifestValue,          "manifest.value",            Input) \
    X(MediaNotFound,          "media.not-found",           Input) \
    X(MediaSizeMismatch,      "media.size-mismatch",       Report) \
    X(MediaSupplied,          "media.supplied",            Report) \
    X(MediaStandIn,           "media.stand-in",            Report) \
    X(MediaUnknownStandIn,    "media.unknown-stand-in",    Report) \
    X(Process,                "process",                   Output) \
    X(ScriptEvent,            "script.event",              Input) \
    X(ScriptJson,             "script.json",               Input) \
    X(ScriptKey,              "script.key",                Input) \
    X(ShaderCompile,          "shader.compile",            Shader) \
    X(ShaderLink,             "shader.link",               Shader) \
    X(ShaderNonAscii,         "shader.non-ascii",          Shader) \
    X(ShaderNul,              "shader.nul",                Shader) \
    X(ShaderPreprocess,       "shader.preprocess",         Shader) \
    X(ShaderPreprocessed,     "shader.preprocessed",       Report) \
    X(SoundChannel,           "sound.channel",             Input) \
    X(SoundEncode,            "sound.encode",              Output) \
    X(SoundFfmpegMissing,     "sound.ffmpeg-missing",      Output) \
    X(SoundMissing,           "sound.missing",             Input) \
    X(SoundSkipped,           "sound.skipped",             Report) \
    X(StateBuffers,           "state.buffers",             Input) \
    X(StateSize,              "state.size",                Input) \
    X(Usage,                  "usage",                     Usage) \
    X(UsageDate,              "usage.date",                Usage) \
    X(UsageOut,               "usage.out",                 Usage) \
    X(UsagePasses,            "usage.passes",              Usage) \
    X(UsageResume,            "usage.resume",              Usage) \
    X(UsageSize,              "usage.size",                Usage) \
    X(VideoDecode,            "video.decode",              Input) \
    X(VideoDevice,            "video.device",              Input) \
    X(VideoNoFfmpeg,          "video.no-ffmpeg",           Input) \
    X(VideoNoFrames,          "video.no-frames",           Input) \
    X(VideoNoStream,          "video.no-stream",           Input) \
    X(VideoProbe,             "video.probe",               Input) \
    X(VideoRate,              "video.rate",                Input) \
    X(VideoRead,              "video.read",                Input) \
    X(VideoSize,              "video.size",                Input) \
    X(VideoStillImage,        "video.still-image",         Report) \
    X(VolumeDecode,           "volume.decode",             Input) \
    X(WatchdogCompile,        "watchdog.compile",          Watchdog) \
    X(WatchdogFrame,          "watchdog.frame",            Watchdog) \
    X(WatchdogInput,          "watchdog.input",            Watchdog) \
    X(WatchdogOutput,         "watchdog.output",           Watchdog) \
    X(WatchChanged,           "watch.changed",             Report) \
    X(WindowCreate,           "window.create",             Gl) \
    X(WindowHelp,             "window.help",               Report) \
    X(WindowInit,             "window.init",               Gl) \
    X(WindowReload,           "window.reload",             Report) \
    X(WindowScreenshot,       "window.screenshot",         Report)

enum class Code : std::uint16_t {
#define TOYHOST_CODE_ENUMERATOR(name, text, category) name,
    TOYHOST_DIAGNOSTIC_CODES(TOYHOST_CODE_ENUMERATOR)
#undef TOYHOST_CODE_ENUMERATOR
};

// The code's stable text ("manifest.value").
TOYHOST_API std::string_view codeName(Code code);
TOYHOST_API Category categoryOf(Code code);
// "usage", "input", "shader", ...
TOYHOST_API std::string_view categoryName(Category category);

}  // namespace toyhost
