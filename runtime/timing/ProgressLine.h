// ProgressLine: the one-line progress text of a run ("frame 120/600  5.3 fps  ETA 1:30
// 12.4 MiB written") and a window's title. Formatting only; the CLI and the window driver decide
// when and where to show them. No GL needed.
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

// What a window's title shows: the shadertoy, the measured frame rate (empty: not measured yet),
// iFrame and iTime of the shown frame (shownFrame < 0: none yet), "paused", and the current
// problem ("" when none): "name | 59 fps | iFrame 120 | iTime 2.00 | paused (F6) | problem".
struct WindowTitle {
    std::string name;
    std::optional<double> frameRate;
    int shownFrame = -1;
    double time = 0;
    bool paused = false;
    std::string problem;
};
std::string formatWindowTitle(const WindowTitle& title);


// "0:07", "12:34", "1:02:03"; rounds to whole seconds.
std::string formatDuration(double seconds);

}  // namespace toyhost
