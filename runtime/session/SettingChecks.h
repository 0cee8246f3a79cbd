// SettingChecks: one check per number a user gives a run (the CLI's flags, the library's
// SessionSettings, Python's keywords), each with one message. The error names the setting in
// Diagnostic::field ("size", "fps", "frame_timeout"), not a CLI flag: a library caller reads
// "size: canvas size 0x0 is not between 1x1 and 16384x16384", and the CLI shows its own flag
// there (tools/toyhost/SessionFlags.h). prepareSession runs them once for every session (a run's,
// a library Session's, each of compare's); the CLI runs only those of its own flags (--frames,
// --mouse) that no session sees. No GL needed.
#pragma once

#include <string>

#include <toyhost/Settings.h>

#include "core/Result.h"

namespace toyhost {

// A usage error about `setting`.
Error settingError(const std::string& setting, std::string message, Code code = Code::Usage);

Status checkSizeSetting(int width, int height);                   // "size"
Status checkFramesSetting(int frames);                            // "frames"
Status checkFpsSetting(double fps);                               // "fps"
Status checkStartTimeSetting(double seconds);                     // "start_time"
Status checkMouseSetting(double x, double y);                     // "mouse"
Status checkTimeoutSetting(const std::string& setting, double seconds);  // "frame_timeout", "compile_timeout"
// A frame's clock given by a caller (Session::stepAt): iTime finite within +-1e9 s ("time"),
// iTimeDelta finite and not negative ("time_delta"), iFrameRate finite and not negative
// ("frame_rate").
Status checkFrameClockSetting(double time, double timeDelta, double frameRate);
// An input event's numbers: mouse coordinates as checkMouseSetting ("mouse"), a keyCode 0..255
// ("key").
Status checkInputEventSetting(bool mouse, double x, double y, bool key, int keyCode);
// The Sound pass's length: more than 0 and at most defaults::kMaxSoundSeconds ("seconds").
Status checkSoundSecondsSetting(double seconds);
// Supersample 1..kMaxSupersample, motion blur 1..kMaxMotionBlurSamples, a shutter in (0, 360] and
// at most kMaxSamplesPerFrame draws a frame: "supersample", "motion_blur", "shutter".
Status checkSamplingSettings(int supersample, int motionBlur, double shutterDegrees);
// A shutter the caller gave (`user`) while the settings before defaults (`given`: the manifest's
// and a checkpoint's merged in) have no motion blur: refused naming "shutter".
Status checkShutterGiven(const SessionSettings& user, const SessionSettings& given);

// The validation table of SessionSettings: one check per row of the list (toyhost/Settings.h),
// declared from it, so that a row without its check does not link. Each sees the settings as the
// session will run them (given values, then the manifest's and toyhost's defaults) and returns the
// error naming its setting. Shared checks (size: width and height; sampling: supersample,
// motion_blur, shutter) run for each of their rows and give the same message.
struct SettingContext {
    // A canvas drawn in tiles (beyond one GL target): its size is checked with the manifest and
    // --tile by checkTiledSize (session/SessionOptions.cpp), not by the size rows.
    bool tiled = false;
};
#define TOYHOST_SETTING_CHECK(Type, member, key, initial, fallback) \
    Status settingCheck_##member(const SessionSettings& settings, const SettingContext& context);
TOYHOST_SESSION_SETTINGS(TOYHOST_SETTING_CHECK)
#undef TOYHOST_SETTING_CHECK
// Every row's check, in the list's order: the first error.
Status checkSessionSettings(const SessionSettings& settings, const SettingContext& context);

}  // namespace toyhost
