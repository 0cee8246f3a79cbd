// toyhost/Settings.h (public API, stable): how a session runs (SessionSettings), as one list of
// fields. The list makes the struct, the checks a session runs on it (one per field, in toyhost's
// session layer), Python's keyword arguments and its toyhost.defaults() keys; a test fails when a
// row lacks any of them. Vocabulary only: no class of the engine behind it. No GL needed.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <toyhost/Defaults.h>
#include <toyhost/Export.h>

// One row per setting: X(Type, member, key, initial, fallback)
// - Type member = initial: the SessionSettings field. An absent optional, an empty list, a false
//   or a 0 is "not given".
// - key: the setting's name in messages (Diagnostic::field), as Python's keyword argument and in
//   toyhost.defaults(); width and height are one setting, "size" (Python: size=(w, h)).
// - fallback: what a session takes when the setting is not given: a member of toyhost::Defaults
//   (toyhost/Defaults.h; a shadertoy manifest's "defaults" come first where it has the setting), or
//   `initial` when the initial value is itself the behaviour (no media, no script, iDate = now).
// Each row has a check in toyhost's session layer (runtime/session/SettingChecks.h,
// settingCheck_<member>), which the build requires. Adding a setting is one line here plus its
// check; `python3 -m toyhost._signature --write .` then rewrites Python's Session signature and its
// docs line (python/tests/test_defaults.py fails until it is run).
#define TOYHOST_SESSION_SETTINGS(X)                                                                   \
    X(std::optional<int>, width, "size", {}, width)                                                   \
    X(std::optional<int>, height, "size", {}, height)                                                 \
    X(std::optional<double>, fps, "fps", {}, fps)                                                     \
    X(double, startTime, "start_time", 0, initial)                                                    \
    X(std::optional<std::string>, date, "date", {}, initial)                                          \
    X(std::vector<std::filesystem::path>, mediaFolders, "media_folders", {}, initial)                 \
    X(TOYHOST_SETTINGS_MEDIA_FILES, mediaFiles, "media_files", {}, initial)                           \
    X(bool, floatImage, "float_image", false, initial)                                                \
    X(std::optional<double>, frameTimeout, "frame_timeout", {}, frameTimeoutSeconds)                  \
    X(std::optional<double>, compileTimeout, "compile_timeout", {}, compileTimeoutSeconds)            \
    X(std::optional<std::filesystem::path>, mouseScript, "mouse_script", {}, initial)                 \
    X(std::optional<std::filesystem::path>, keyScript, "key_script", {}, initial)                     \
    X(std::optional<int>, supersample, "supersample", {}, supersample)                                \
    X(std::optional<int>, motionBlur, "motion_blur", {}, motionBlur)                                  \
    X(std::optional<double>, shutterDegrees, "shutter", {}, shutterDegrees)                           \
    X(bool, dither, "dither", false, initial)                                                         \
    X(std::optional<std::string>, shutterOffset, "shutter_offset", {}, initial)                       \
    X(std::optional<std::string>, sampleSpace, "sample_space", {}, initial)                           \
    X(std::vector<std::string>, defines, "defines", {}, initial)

// A type with a comma cannot stand in a macro argument.
#define TOYHOST_SETTINGS_MEDIA_FILES std::vector<std::pair<std::string, std::filesystem::path>>

namespace toyhost {

// How a session runs. An absent setting takes the default (the shadertoy manifest's "defaults",
// else toyhost's own: toyhost/Defaults.h); a value given is checked, and refused with an error
// naming the setting (Diagnostic::field "size", "fps", ...) when out of range: width = 0 is an
// error, not the default.
// - width, height: the canvas (iResolution); give both or neither.
// - fps: step() renders frame n at iTime = startTime + n / fps, iTimeDelta = 1 / fps.
// - date: iDate at time 0 as "YYYY-MM-DDTHH:MM:SS" (local time); absent: now. Fixed dates make
//   runs repeatable.
// - mediaFolders, mediaFiles: real files for Shadertoy's stock media (by hash or name; mediaFiles
//   maps a stock id or name to a file), else deterministic stand-ins.
// - floatImage: Image rendered into RGBA32F instead of RGBA8 (what the screen shows): read(...,
//   float) then gives Image's unclamped floats.
// - frameTimeout, compileTimeout: limits in seconds (0: none): a pass drawing one frame, or
//   compiling, for longer makes the call that was running return an error once it returns (GL
//   cannot be interrupted). Absent: none for a Session; the toyhost commands' own defaults for them.
// - mouseScript, keyScript: input scripts (the CLI's --mouse-script / --key-script JSON files) that
//   step() replays by frame number before the caller's own events, as a headless run does.
// - supersample, motionBlur, shutterDegrees, dither: better pixels than the site
//   (docs/sampling.md): the Image pass drawn supersample x supersample times with fragCoord on a
//   regular grid inside each pixel, at motionBlur times inside the shutter interval
//   (shutterDegrees / 360 of the frame step, opening at the frame's time), every pair drawn and the
//   draws averaged; buffers, Cube A and Sound still run once per frame. `dither`: an 8x8 ordered
//   dither before the average is rounded to 8 bits. 1, 1: the site's pixels, byte for byte.
//   shutterDegrees needs motionBlur. shutterOffset: "open" (absent: the interval opens at the
//   frame's time), "centre" or "close". sampleSpace: "linear" (absent: the draws averaged in
//   linear light) or "display" (their display values averaged, the site's pixels box-filtered).
// - defines: macros added to every pass after the site's header, before Common: "NAME" (defined as
//   1) or "NAME=VALUE", as the CLI's --define. A name is a GLSL identifier without GLSL ES's
//   reserved GL_ prefix or "__"; a name given twice with different values is refused.
struct SessionSettings {
#define TOYHOST_SETTINGS_MEMBER(Type, member, key, initial, fallback) Type member = initial;
    TOYHOST_SESSION_SETTINGS(TOYHOST_SETTINGS_MEMBER)
#undef TOYHOST_SETTINGS_MEMBER
};

// The list as data, for bindings and tests: each row's member and key, and its fallback's name
// (a toyhost::Defaults member, or "initial").
struct SettingField {
    const char* member;
    const char* key;
    const char* fallback;
};
TOYHOST_API std::span<const SettingField> settingFields();

}  // namespace toyhost
