// JoinFrames: encodes a complete sequence of PNG frames into one video through the capture
// module's VideoSink (ffmpeg; the same encoder settings as `run --out movie.mp4`), optionally
// with a sound track. CPU only; no GL.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include "capture/VideoSink.h"
#include "core/Result.h"

namespace toyhost {

// Decodes `frames` in order and writes them to `out` at `fps`. Every frame must be a PNG of the
// first one's size; an error names the first one that is not, and leaves no video behind.
// `stopRequested` (a signal, for the CLI) is asked before each frame: when it says so, ffmpeg is
// killed, its unfinished file removed, and the error is Code::Interrupted.
Status joinFrames(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& out, double fps,
                  const VideoSettings& settings, const std::function<bool()>& stopRequested = {});

}  // namespace toyhost
