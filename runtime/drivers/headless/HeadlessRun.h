// HeadlessRun: the `toyhost run --headless` driver. prepareSession checks everything that needs no GL
// (manifest, images, output pattern, input scripts, ffmpeg) before any GL call; then a Player on
// a headless EGL context renders frames with a fixed time step, input scripts feed it events, and
// a FrameRecorder captures (async readback, encoder threads).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Result.h"
#include "session/SessionObserver.h"
#include "session/SessionOptions.h"

namespace toyhost {


Result<SessionReport> runHeadless(const SessionOptions& options, SessionObserver& observer);

// The files a run with `output` writes for frames [first, end) of 0..frames-1 (one for a video,
// none for raw).
std::vector<std::filesystem::path> capturedFiles(const OutputPattern& output, int first, int end, int frames,
                                                 int captureEvery);

}  // namespace toyhost
