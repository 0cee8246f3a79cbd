// toyhost::runDefaults (include/toyhost/Defaults.h): the public copy of core/Defaults.h's values,
// filled here so that the numbers stay in that one place. No GL needed.
#include <toyhost/Defaults.h>

#include "core/Defaults.h"

namespace toyhost {

Defaults runDefaults() {
    Defaults d;
    d.width = defaults::kCanvasWidth;
    d.height = defaults::kCanvasHeight;
    d.fps = defaults::kFps;
    d.minFps = defaults::kMinFps;
    d.maxFps = defaults::kMaxFps;
    d.maxCanvasSide = defaults::kMaxCanvasSide;
    d.frames = defaults::kFrames;
    d.compareFrames = defaults::kCompareFrames;
    d.captureEvery = defaults::kCaptureEvery;
    d.pngLevel = defaults::kPngLevel;
    d.captureMemoryMiB = defaults::kCaptureMemoryMiB;
    d.sampleRate = defaults::kSampleRate;
    d.soundSeconds = defaults::kSoundSeconds;
    d.frameTimeoutSeconds = defaults::kFrameTimeoutSeconds;
    d.compileTimeoutSeconds = defaults::kCompileTimeoutSeconds;
    return d;
}

}  // namespace toyhost
