#include "session/SettingChecks.h"

#include <cmath>
#include <string>
#include <system_error>

#include "core/AtomicFile.h"
#include "core/Defaults.h"
#include "player/PlayerDesc.h"
#include "shader/MacroDefines.h"
#include "timing/SamplePattern.h"
#include "timing/FrameClock.h"

namespace toyhost {

Error settingError(const std::string& setting, std::string message, Code code) {
    Error error(std::move(message), code);
    error.diagnostics.front().field = setting;
    return error;
}

Status checkSizeSetting(int width, int height) {
    if (Status size = checkCanvasSize(width, height); !size)
        return settingError("size", size.error().first().message, size.error().first().code);
    return okStatus();
}

Status checkFramesSetting(int frames) {
    if (frames < 1) return settingError("frames", "must be at least 1");
    return okStatus();
}

Status checkFpsSetting(double fps) {
    if (!std::isfinite(fps) || fps < defaults::kMinFps || fps > defaults::kMaxFps)
        return settingError("fps", "must be a number of frames per second from 0.001 to 1000000");
    return okStatus();
}

Status checkStartTimeSetting(double seconds) {
    if (!std::isfinite(seconds) || std::abs(seconds) > defaults::kMaxSeconds)
        return settingError("start_time", "must be a number of seconds between -1e9 and 1e9");
    return okStatus();
}

Status checkMouseSetting(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > defaults::kMaxPixelCoordinate ||
        std::abs(y) > defaults::kMaxPixelCoordinate)
        return settingError("mouse", "coordinates must be within +-1000000 pixels");
    return okStatus();
}

Status checkTimeoutSetting(const std::string& setting, double seconds) {
    if (!std::isfinite(seconds) || seconds < 0 || (seconds > 0 && seconds < defaults::kMinTimeoutSeconds) ||
        seconds > defaults::kMaxTimeoutSeconds)
        return settingError(setting, "must be 0 (off) or a number of seconds from 0.1 to 1000000");
    return okStatus();
}

Status checkFrameClockSetting(double time, double timeDelta, double frameRate) {
    if (!std::isfinite(time) || std::abs(time) > defaults::kMaxSeconds)
        return settingError("time", "must be a number of seconds between -1e9 and 1e9");
    if (!std::isfinite(timeDelta) || timeDelta < 0 || timeDelta > defaults::kMaxSeconds)
        return settingError("time_delta", "must be a number of seconds, 0 or more");
    if (!std::isfinite(frameRate) || frameRate < 0 || frameRate > defaults::kMaxFps)
        return settingError("frame_rate", "must be 0 or a number of frames per second up to 1000000");
    return okStatus();
}

Status checkInputEventSetting(bool mouse, double x, double y, bool key, int keyCode) {
    if (mouse)
        if (Status at = checkMouseSetting(x, y); !at) return at;
    if (key && (keyCode < 0 || keyCode > 255))
        return settingError("key", "a keyCode is 0 to 255 (the keyboard texture's columns), got " + std::to_string(keyCode));
    return okStatus();
}

Status checkSoundSecondsSetting(double seconds) {
    if (!(seconds > 0 && seconds <= defaults::kMaxSoundSeconds))
        return settingError("seconds", "the sound's length must be more than 0 and at most " +
                                           std::to_string(static_cast<int>(defaults::kMaxSoundSeconds)) + " seconds");
    return okStatus();
}

Status checkSamplingSettings(int supersample, int motionBlur, double shutterDegrees) {
    using namespace defaults;
    if (supersample < 1 || supersample > kMaxSupersample)
        return settingError("supersample", "must be 1 to " + std::to_string(kMaxSupersample) +
                                               " (samples per pixel side), got " + std::to_string(supersample));
    if (motionBlur < 1 || motionBlur > kMaxMotionBlurSamples)
        return settingError("motion_blur", "must be 1 to " + std::to_string(kMaxMotionBlurSamples) +
                                               " (samples per frame), got " + std::to_string(motionBlur));
    if (!(shutterDegrees > 0 && shutterDegrees <= 360))
        return settingError("shutter", "must be an angle more than 0 and at most 360 degrees");
    const long long draws = static_cast<long long>(supersample) * supersample * motionBlur;
    if (draws > kMaxSamplesPerFrame)
        return settingError("supersample", std::to_string(supersample) + " x " + std::to_string(supersample) + " x " +
                                               std::to_string(motionBlur) + " motion samples = " +
                                               std::to_string(draws) + " draws a frame, more than " +
                                               std::to_string(kMaxSamplesPerFrame));
    return okStatus();
}

// --- the validation table: one check per row of toyhost/Settings.h ------------------------------

Status settingCheck_width(const SessionSettings& s, const SettingContext& context) {
    if (context.tiled || !s.width || !s.height) return okStatus();
    return checkSizeSetting(*s.width, *s.height);
}

Status settingCheck_height(const SessionSettings& s, const SettingContext& context) {
    return settingCheck_width(s, context);  // one setting, "size"
}

Status settingCheck_fps(const SessionSettings& s, const SettingContext&) {
    return s.fps ? checkFpsSetting(*s.fps) : okStatus();  // absent in a window: real time
}

Status settingCheck_startTime(const SessionSettings& s, const SettingContext&) { return checkStartTimeSetting(s.startTime); }

Status settingCheck_date(const SessionSettings& s, const SettingContext&) {
    if (!s.date) return okStatus();
    Result<double> parsed = parseWallClock(*s.date);
    if (!parsed) return settingError("date", parsed.error().first().message);
    return okStatus();
}

Status settingCheck_mediaFolders(const SessionSettings& s, const SettingContext&) {
    namespace fs = std::filesystem;
    for (const fs::path& folder : s.mediaFolders) {
        std::error_code ec;
        if (!fs::is_directory(folder, ec))
            return fileError(folder.string(),
                             fs::exists(folder, ec) ? "is not a folder (--media or $TOYHOST_MEDIA)"
                                                    : "media folder not found (--media or $TOYHOST_MEDIA)",
                             Code::IoNotFound);
    }
    return okStatus();
}

Status settingCheck_mediaFiles(const SessionSettings& s, const SettingContext&) {
    for (const auto& [id, file] : s.mediaFiles) {
        if (Status regular = checkRegularFile(file); !regular) {
            Error error = regular.error();
            error.diagnostics.front().message += " (--media-file " + id + ")";
            return error;
        }
    }
    return okStatus();
}

// Both values are meaningful; nothing to refuse.
Status settingCheck_floatImage(const SessionSettings&, const SettingContext&) { return okStatus(); }

Status settingCheck_frameTimeout(const SessionSettings& s, const SettingContext&) {
    return s.frameTimeout ? checkTimeoutSetting("frame_timeout", *s.frameTimeout) : okStatus();
}

Status settingCheck_compileTimeout(const SessionSettings& s, const SettingContext&) {
    return s.compileTimeout ? checkTimeoutSetting("compile_timeout", *s.compileTimeout) : okStatus();
}

// The scripts' contents are parsed where they are read (prepareSession), with line and column.
Status settingCheck_mouseScript(const SessionSettings& s, const SettingContext&) {
    return s.mouseScript ? checkRegularFile(*s.mouseScript) : okStatus();
}

Status settingCheck_keyScript(const SessionSettings& s, const SettingContext&) {
    return s.keyScript ? checkRegularFile(*s.keyScript) : okStatus();
}

namespace {
Status checkSampling(const SessionSettings& s) {
    return checkSamplingSettings(s.supersample.value_or(defaults::kSupersample),
                                 s.motionBlur.value_or(defaults::kMotionBlurSamples),
                                 s.shutterDegrees.value_or(defaults::kShutterDegrees));
}
}  // namespace

Status settingCheck_supersample(const SessionSettings& s, const SettingContext&) { return checkSampling(s); }
Status settingCheck_motionBlur(const SessionSettings& s, const SettingContext&) { return checkSampling(s); }
// A shutter given without motion blur is refused before the defaults are applied (prepareSession:
// checkShutterGiven), as this check sees the default shutter too.
Status settingCheck_shutterDegrees(const SessionSettings& s, const SettingContext&) { return checkSampling(s); }

Status checkShutterGiven(const SessionSettings& user, const SessionSettings& given) {
    // As a dither without samples: a shutter without motion blur would be ignored.
    if (user.shutterDegrees && given.motionBlur.value_or(defaults::kMotionBlurSamples) == 1)
        return settingError("shutter", "sets the interval of motion blur: give motion_blur too");
    return okStatus();
}

Status settingCheck_shutterOffset(const SessionSettings& s, const SettingContext&) {
    if (!s.shutterOffset) return okStatus();
    if (!parseShutterOffset(*s.shutterOffset))
        return settingError("shutter_offset", "must be open, centre or close, got '" + *s.shutterOffset + "'");
    if (s.motionBlur.value_or(defaults::kMotionBlurSamples) == 1)
        return settingError("shutter_offset", "places the interval of motion blur: give motion_blur too");
    return okStatus();
}

Status settingCheck_sampleSpace(const SessionSettings& s, const SettingContext&) {
    if (s.sampleSpace && !parseSampleSpaceLinear(*s.sampleSpace))
        return settingError("sample_space", "must be linear or display, got '" + *s.sampleSpace + "'");
    return okStatus();
}

Status settingCheck_dither(const SessionSettings& s, const SettingContext&) {
    const SamplingDesc sampling{s.supersample.value_or(defaults::kSupersample),
                                s.motionBlur.value_or(defaults::kMotionBlurSamples),
                                s.shutterDegrees.value_or(defaults::kShutterDegrees), s.dither};
    if (sampling.dither && isSingleSample(sampling))
        return settingError("dither", "dithers an average of samples: give supersample or motion_blur too");
    return okStatus();
}

Status settingCheck_defines(const SessionSettings& s, const SettingContext&) {
    Result<MacroDefines> defines = parseMacroDefines(s.defines);
    return defines ? okStatus() : Status(defines.error());
}

Status checkSessionSettings(const SessionSettings& settings, const SettingContext& context) {
#define TOYHOST_RUN_SETTING_CHECK(Type, member, key, initial, fallback) \
    if (Status checked = settingCheck_##member(settings, context); !checked) return checked;
    TOYHOST_SESSION_SETTINGS(TOYHOST_RUN_SETTING_CHECK)
#undef TOYHOST_RUN_SETTING_CHECK
    return okStatus();
}

}  // namespace toyhost
