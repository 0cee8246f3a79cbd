// toyhost/Defaults.h (public API, stable): the values a run takes for what neither its settings
// nor the shadertoy's manifest say, and the bounds settings are checked against. This list is the
// one place these numbers are written: toyhost's engine (runtime/core/Defaults.h) takes its
// constants from it, the commands show them in --help, Python's toyhost.defaults() is made from
// it. No GL needed.
#pragma once

#include <cstddef>

#include <toyhost/Export.h>

// One row per default: X(Type, member, key, value, what). `key` is the name in Python's
// toyhost.defaults() (and the setting's name where the default belongs to a SessionSettings field:
// toyhost/Settings.h names it in its `fallback` column). Adding a default is one line here.
#define TOYHOST_DEFAULTS(X)                                                                                          \
    X(int, width, "width", 800, "canvas (iResolution) for SessionSettings without width/height")                  \
    X(int, height, "height", 450, "")                                                                              \
    X(double, fps, "fps", 60.0, "fixed time step: frame n at iTime = startTime + n / fps")                         \
    X(double, minFps, "min_fps", 0.001, "the range fps may be given in (beyond it iTime is no usable number)")    \
    X(double, maxFps, "max_fps", 1e6, "")                                                                          \
    X(int, maxCanvasSide, "max_canvas_side", 16384, "the largest width or height drawn at once (larger: tiled)")  \
    X(int, frames, "frames", 1, "frames `toyhost run` renders")                                                    \
    X(int, compareFrames, "compare_frames", 10, "frames compareShadertoys() renders when nothing says")           \
    X(int, captureEvery, "capture_every", 1, "`toyhost run --capture-every`")                                      \
    X(int, pngLevel, "png_level", 1, "zlib level of written PNG files (fastest compression)")                     \
    X(std::size_t, captureMemoryMiB, "capture_memory_mib", 256, "captured frames waiting for the encoders")       \
    X(double, sampleRate, "sample_rate", 44100.0, "iSampleRate in every pass")                                     \
    X(double, soundSeconds, "sound_seconds", 180.0, "length of the Sound pass's output (the site's)")             \
    X(double, frameTimeoutSeconds, "frame_timeout", 60.0, "the commands' watchdog limits in seconds; a library "  \
                                                          "Session has none unless its settings give them")        \
    X(double, compileTimeoutSeconds, "compile_timeout", 120.0, "")                                                 \
    X(int, supersample, "supersample", 1, "samples averaged into a frame: one per pixel at one instant unless "   \
                                          "asked (timing/SamplePattern.h)")                                        \
    X(int, motionBlur, "motion_blur", 1, "")                                                                       \
    X(double, shutterDegrees, "shutter", 180.0, "open half the frame step: the film convention")                  \
    X(int, maxSupersample, "max_supersample", 16, "256 samples per pixel")                                         \
    X(int, maxMotionBlur, "max_motion_blur", 256, "")                                                              \
    X(int, maxSamplesPerFrame, "max_samples_per_frame", 4096, "supersample^2 x motion blur draws a frame")

namespace toyhost {

// Every default of the list above; a default-constructed Defaults holds them (constexpr).
struct Defaults {
#define TOYHOST_DEFAULTS_MEMBER(Type, member, key, value, what) Type member = value;
    TOYHOST_DEFAULTS(TOYHOST_DEFAULTS_MEMBER)
#undef TOYHOST_DEFAULTS_MEMBER
};

// Named runDefaults, not defaults: toyhost's code keeps its constants in a namespace by that name.
TOYHOST_API Defaults runDefaults();

}  // namespace toyhost
