// toyhost/Defaults.h (public API, stable): the values a run takes for what neither its settings
// nor the shadertoy's manifest say, and the bounds settings are checked against; the same numbers
// the toyhost commands show in --help (their one place is toyhost's runtime/core/Defaults.h).
// No GL needed.
#pragma once

#include <cstddef>

#include <toyhost/Export.h>

namespace toyhost {

struct Defaults {
    int width = 0;                     // canvas (iResolution), for SessionSettings without width/height
    int height = 0;
    double fps = 0;                    // fixed time step: frame n at iTime = startTime + n / fps
    double minFps = 0;                 // the range fps may be given in
    double maxFps = 0;
    int maxCanvasSide = 0;             // the largest width or height asked for (before GL's limit)
    int frames = 0;                    // frames `toyhost run` renders
    int compareFrames = 0;             // frames compareShadertoys() renders when nothing says
    int captureEvery = 0;              // `toyhost run --every`
    int pngLevel = 0;                  // zlib level of written PNG files
    std::size_t captureMemoryMiB = 0;  // captured frames waiting for the encoders, at most
    double sampleRate = 0;             // iSampleRate in every pass
    double soundSeconds = 0;           // length of the Sound pass's output
    // The toyhost commands' watchdog limits in seconds; a Session's are 0 (none) unless its
    // settings give them.
    double frameTimeoutSeconds = 0;
    double compileTimeoutSeconds = 0;
    // Samples averaged into a frame (SessionSettings supersample, motionBlur, shutterDegrees) and
    // their bounds.
    int supersample = 0;
    int motionBlur = 0;
    double shutterDegrees = 0;
    int maxSupersample = 0;
    int maxMotionBlur = 0;
    int maxSamplesPerFrame = 0;
};

// Named runDefaults, not defaults: toyhost's code keeps its constants in a namespace by that name.
TOYHOST_API Defaults runDefaults();

}  // namespace toyhost
