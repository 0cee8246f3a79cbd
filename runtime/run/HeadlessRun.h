// HeadlessRun: the `toyhost run --headless` job. Validates everything (manifest, output
// pattern, input scripts, ffmpeg for videos) before any GL call, then renders frames with a fixed
// time step on an EGL surfaceless context and hands captured frames to FrameCapture (async
// readback, encoder threads). Creates its own context.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "capture/VideoSink.h"
#include "core/Result.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

struct RunOptions {
    std::filesystem::path target;          // folder with manifest.json, or the manifest file
    int width = 800;
    int height = 450;
    int frames = 1;
    double fps = 60;
    double startTime = 0;
    std::optional<std::string> outPattern;
    int captureEvery = 1;
    PassId capturePass = PassId::Image;
    std::optional<glm::vec2> mouse;        // --mouse X,Y: pressed on frame 0 and held
    std::optional<std::filesystem::path> mouseScript;
    std::optional<std::filesystem::path> keyScript;
    std::vector<std::pair<std::string, std::filesystem::path>> mediaFiles;  // id -> file
    std::vector<std::filesystem::path> mediaFolders;
    std::optional<double> wallClock;       // iDate at frame 0 (FrameClock form); default: now

    // Capture pipeline (runtime/capture).
    int pngLevel = 1;                      // zlib level of PNG files, 0..9; 1 is fast
    bool syncCapture = false;              // read back and encode on the render thread (reference path)
    int encoderThreads = 0;                // 0: defaultEncoderThreads()
    std::size_t captureMemoryBytes = std::size_t(256) << 20;  // cap on frames waiting for encoders
    VideoSettings video;                   // codec and quality of --out x.mp4|.webm|.mov|.mkv
    int rawStreamFd = 1;                   // where --out - writes
    // glFinish after every frame. For benchmarks: llvmpipe drops queued work that a later draw
    // fully overwrites before anything reads it, so an unsynchronised render-only loop does not
    // measure the shading cost.
    bool finishEachFrame = false;
};

// Frames n with n % captureEvery == 0, and the last frame.
inline bool isCapturedFrame(int frame, int frames, int captureEvery) {
    return frame % captureEvery == 0 || frame == frames - 1;
}

struct RunReport {
    std::string manifestName;
    std::string context;                   // GL backend description
    int framesRendered = 0;
    std::vector<std::filesystem::path> files;
    double seconds = 0;                    // wall time of the frame loop, GPU and encoders included
    double firstFrameSeconds = 0;          // from start of run() to the first frame finished
    std::uint64_t bytesWritten = 0;        // by the capture (file sizes; the video's size)
    int encoderThreads = 0;                // encoder threads the capture used (0: synchronous)
};

// Where a run stands, reported after every frame.
struct RunProgress {
    int framesDone = 0;
    int frames = 0;
    double seconds = 0;                    // since the frame loop started
    std::uint64_t bytesWritten = 0;        // so far (encoders run behind the render loop)
};

// Receives what a run has to say while it runs; the CLI decides how to show it.
class RunObserver {
public:
    virtual ~RunObserver() = default;
    virtual void notice(const std::string& line) = 0;
    // Called on the render thread after every frame; keep it cheap.
    virtual void progress(const RunProgress& progress) { (void)progress; }
    // Polled before every frame; true ends the run with an "interrupted" error, cleanly (a video
    // being encoded is discarded, image files already written stay).
    virtual bool stopRequested() const { return false; }
};

Result<RunReport> runHeadless(const RunOptions& options, RunObserver& observer);

}  // namespace toyhost
