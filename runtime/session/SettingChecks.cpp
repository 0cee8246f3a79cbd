#include "session/SettingChecks.h"

#include <cmath>
#include <string>

#include "core/Defaults.h"
#include "player/PlayerDesc.h"

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

}  // namespace toyhost
