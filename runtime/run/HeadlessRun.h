// HeadlessRun: the `toyhost run --headless` job. Validates everything (manifest, output
// pattern, input scripts) before any GL call, then renders frames with a fixed time step on an
// EGL surfaceless context and hands captured frames to image files. Creates its own context.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

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
    double seconds = 0;                    // wall time of the frame loop
    double firstFrameSeconds = 0;          // from start of run() to the first frame finished
};

// Receives what a run has to say while it runs; the CLI decides how to show it.
class RunObserver {
public:
    virtual ~RunObserver() = default;
    virtual void notice(const std::string& line) = 0;
    virtual void frameDone(int frame, int frames) { (void)frame, (void)frames; }
};

Result<RunReport> runHeadless(const RunOptions& options, RunObserver& observer);

}  // namespace toyhost
