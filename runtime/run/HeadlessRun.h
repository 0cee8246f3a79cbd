// HeadlessRun: the `toyhost run --headless` driver. prepareRun checks everything that needs no GL
// (manifest, images, output pattern, input scripts, ffmpeg) before any GL call; then a Player on
// a headless EGL context renders frames with a fixed time step, input scripts feed it events, and
// a FrameRecorder captures (async readback, encoder threads).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Result.h"
#include "run/RunObserver.h"
#include "run/RunOptions.h"

namespace toyhost {

struct RunReport {
    std::string manifestName;
    std::string context;                   // GL backend description
    int width = 0;
    int height = 0;
    int framesRendered = 0;
    std::vector<std::filesystem::path> files;
    double seconds = 0;                    // wall time of the frame loop, GPU and encoders included
    double firstFrameSeconds = 0;          // from start of run() to the first frame finished
    std::uint64_t bytesWritten = 0;        // by the capture (file sizes; the video's size)
    int encoderThreads = 0;                // encoder threads the capture used (0: synchronous)
};

Result<RunReport> runHeadless(const RunOptions& options, RunObserver& observer);

// The files a run with `output` writes for frames 0..frames-1 (one for a video, none for raw).
std::vector<std::filesystem::path> capturedFiles(const OutputPattern& output, int frames, int captureEvery);

}  // namespace toyhost
