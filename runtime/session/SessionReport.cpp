#include <cstdio>

#include "core/Defaults.h"
#include "session/SessionObserver.h"

namespace toyhost {

namespace {
std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// "350.2 ms", "4.812 s" (benchmarks read these).
std::string duration(double seconds) {
    if (seconds < 1.0) return format("%.1f ms", seconds * 1000.0);
    return format("%.3f s", seconds);
}
}  // namespace

std::vector<std::string> summaryLines(const SessionReport& r) {
    std::vector<std::string> lines;
    const std::string where = r.mode + " on " + r.context;
    const std::string startup = "start-up " + duration(r.startupSeconds);
    if (r.soundSeconds > 0) {
        lines.push_back(r.name + ": " + format("%g", r.soundSeconds) + " s of stereo sound rendered at " +
                        std::to_string(static_cast<int>(defaults::kSampleRate)) + " Hz, " + where + ": " + startup +
                        ", rendering " + duration(r.firstFrameSeconds) + ", writing " + duration(r.restSeconds));
    } else if (r.frames == 0) {
        lines.push_back(r.name + ": no frame rendered at " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                        ", " + where + ": " + startup);
    } else {
        std::string line = r.name + ": " + std::to_string(r.frames) + (r.frames == 1 ? " frame" : " frames") + " at " +
                           std::to_string(r.width) + "x" + std::to_string(r.height) +
                           (r.samplesPerFrame > 1 ? " (" + std::to_string(r.samplesPerFrame) + " samples each)" : "") +
                           ", " + where + ": " + startup + ", first frame " + duration(r.firstFrameSeconds);
        if (r.frames > 1) {
            const int rest = r.frames - 1;
            const double perFrame = r.restSeconds / rest;
            line += ", then " + std::to_string(rest) + (rest == 1 ? " frame" : " frames") + " in " +
                    duration(r.restSeconds) + " (" + format(perFrame > 0 ? "%.1f" : "%.0f", perFrame > 0 ? 1.0 / perFrame : 0) +
                    " frames/s, " + format(perFrame * 1000.0 < 10.0 ? "%.2f" : "%.1f", perFrame * 1000.0) + " ms/frame" +
                    (r.pausedSeconds > 0 ? "; " + duration(r.pausedSeconds) + " paused, not counted" : "") + ")";
        }
        lines.push_back(line);
    }
    auto bytes = [&] { return formatBytes(r.bytesWritten); };
    if (r.files.size() == 1)
        lines.push_back("wrote " + r.files.front().string() + (r.bytesWritten ? " (" + bytes() + ")" : ""));
    else if (!r.files.empty())
        lines.push_back("wrote " + std::to_string(r.files.size()) + " files (" + bytes() + "): " + r.files.front().string() +
                        " .. " + r.files.back().string());
    else if (r.toStdout && r.soundSeconds > 0)
        lines.push_back("wrote WAV to stdout");
    else if (r.toStdout)
        lines.push_back("wrote " + bytes() + " of raw RGBA8 frames to stdout");
    if (r.captureTimes) {
        const CaptureTimes& t = *r.captureTimes;
        lines.push_back("capture time: render " + duration(t.render) + ", readback " + duration(t.readback) +
                        ", waiting for the encoders " + duration(t.waitingForEncoders) + "; " +
                        std::to_string(r.encoderThreads) + (r.encoderThreads == 1 ? " encoder thread" : " encoder threads") +
                        (r.encoderThreads == 0 ? " (encoding on the render thread)" : "") + ": encode " +
                        duration(t.encode) + ", write " + duration(t.write) +
                        (r.videoEncoder.empty() ? "" : " (video encoder " + r.videoEncoder + ")"));
    }
    if (r.checkpoint) lines.push_back("checkpoint written: " + r.checkpoint->string());
    if (r.files.empty() && !r.toStdout && !r.outputAsked && !r.interactive)
        lines.push_back(std::string(r.checkpoint ? "no frames written" : "no files written") +
                        " (no --out; e.g. --out frame_%04d.png captures the frames)");
    return lines;
}

std::string watchRoundLine(const SessionReport& r) {
    std::string line = std::to_string(r.frames) + (r.frames == 1 ? " frame" : " frames") + " in " +
                       duration(r.firstFrameSeconds + r.restSeconds);
    auto bytes = [&] { return formatBytes(r.bytesWritten); };
    if (r.files.size() == 1)
        line += "; wrote " + r.files.front().string() + (r.bytesWritten ? " (" + bytes() + ")" : "");
    else if (!r.files.empty())
        line += "; wrote " + std::to_string(r.files.size()) + " files (" + bytes() + "): " + r.files.front().string() +
                " .. " + r.files.back().string();
    else if (r.toStdout)
        line += "; wrote " + bytes() + " of raw RGBA8 frames to stdout";
    if (r.checkpoint) line += "; checkpoint " + r.checkpoint->string();
    return line;
}

}  // namespace toyhost
