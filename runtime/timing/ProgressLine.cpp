#include "timing/ProgressLine.h"

#include <cmath>
#include <cstdio>

namespace toyhost {

std::string formatDuration(double seconds) {
    const long long total = seconds > 0 ? std::llround(seconds) : 0;
    char text[32];
    if (total >= 3600)
        std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, (total / 60) % 60, total % 60);
    else
        std::snprintf(text, sizeof text, "%lld:%02lld", total / 60, total % 60);
    return text;
}

std::string formatProgressLine(const RunProgress& p) {
    const double fps = p.seconds > 0 ? p.framesDone / p.seconds : 0;
    char head[96];
    if (p.frames <= 0) {
        std::snprintf(head, sizeof head, "frame %d  %.1f fps", p.framesDone, fps);
    } else {
        std::string eta = "--:--";
        if (fps > 0) eta = formatDuration((p.frames - p.framesDone) / fps);
        std::snprintf(head, sizeof head, "frame %d/%d  %.1f fps  ETA %s", p.framesDone, p.frames, fps, eta.c_str());
    }
    std::string line = head;
    if (p.samplesPerFrame > 1) {
        char samples[64];
        std::snprintf(samples, sizeof samples, "  %d samples/frame (%.1f samples/s)", p.samplesPerFrame,
                      fps * p.samplesPerFrame);
        line += samples;
    }
    if (p.bytesWritten > 0) line += "  " + formatBytes(p.bytesWritten) + " written";
    return line;
}

}  // namespace toyhost
