// ProgressLine: the one-line progress text of a run ("frame 120/600  5.3 fps  ETA 1:30
// 12.4 MiB written"; a window's title is timing/WindowTitle.h). Formatting only; the CLI decides
// when and where to show it. No GL needed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/ByteText.h"  // formatBytes, for the byte counts of progress lines


namespace toyhost {

// Where a run stands, reported after every frame.
struct RunProgress {
    int framesDone = 0;
    int frames = 0;                        // 0: no end (a window run without --frames)
    double seconds = 0;                    // since the frame loop started
    std::uint64_t bytesWritten = 0;        // so far (encoders run behind the render loop)
    int samplesPerFrame = 1;               // draws of Image averaged into a frame
};

std::string formatProgressLine(const RunProgress& progress);

// "0:07", "12:34", "1:02:03"; rounds to whole seconds.
std::string formatDuration(double seconds);

}  // namespace toyhost
