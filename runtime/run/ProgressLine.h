// ProgressLine: the one-line progress text of a run ("frame 120/600  5.3 fps  ETA 1:30
// 12.4 MiB written"). Formatting only; the CLI decides when and where to show it. No GL needed.
#pragma once

#include <cstdint>
#include <string>

#include "run/HeadlessRun.h"

namespace toyhost {

std::string formatProgressLine(const RunProgress& progress);

// "812 B", "3.4 KiB", "12.4 MiB", "1.20 GiB".
std::string formatBytes(std::uint64_t bytes);

// "0:07", "12:34", "1:02:03"; rounds to whole seconds.
std::string formatDuration(double seconds);

}  // namespace toyhost
