#include "capture/VideoEncoderChoice.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <optional>
#include <system_error>
#include <unistd.h>

#include "core/ChildProcess.h"

namespace toyhost {
namespace fs = std::filesystem;

namespace {
// A 2-frame encode of a generated picture into nothing: fails fast where the driver, the device
// or the library behind an encoder is missing.
bool encodesHere(const std::string& codec) {
    std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-nostats", "-loglevel", "error"};
    if (codec == "h264_vaapi") args.insert(args.end(), {"-vaapi_device", "/dev/dri/renderD128"});
    args.insert(args.end(), {"-f", "lavfi", "-i", "color=c=gray:s=256x256:r=30", "-frames:v", "2"});
    if (codec == "h264_vaapi") args.insert(args.end(), {"-vf", "format=nv12,hwupload"});
    args.insert(args.end(), {"-c:v", codec, "-f", "null", "-"});
    std::error_code ec;
    const fs::path log = fs::temp_directory_path(ec) / ("toyhost-codec-probe-" + std::to_string(::getpid()) + ".log");
    Result<ChildProcess> child = ChildProcess::spawn(args, log);
    bool works = false;
    if (child) {
        Result<int> status = child->closeAndWait(/*killAfterMs=*/20000);
        works = status && *status == 0;
    }
    fs::remove(log, ec);
    return works;
}
}  // namespace

const std::vector<std::string>& hardwareH264Encoders() {
    static const std::vector<std::string> encoders = {"h264_nvenc", "h264_vaapi", "h264_qsv"};
    return encoders;
}

std::string VideoEncoderChoice::explanation() const {
    if (hardware) return "--codec auto: using " + codec + " (hardware)";
    std::string line = "--codec auto: using " + codec + " (software)";
    if (!tried.empty()) {
        line += "; no hardware encoder works here (tried";
        for (const std::string& t : tried) line += " " + t;
        line += ")";
    }
    return line;
}

VideoEncoderChoice chooseAutoVideoEncoder(const std::string& container) {
    if (container == ".webm") return {"libvpx-vp9", false, {}};
    static std::mutex mutex;
    static std::optional<VideoEncoderChoice> cached;
    std::lock_guard lock(mutex);
    if (!cached) {
        VideoEncoderChoice choice{"libx264", false, {}};
        for (const std::string& candidate : hardwareH264Encoders()) {
            if (encodesHere(candidate)) {
                choice.codec = candidate;
                choice.hardware = true;
                break;
            }
            choice.tried.push_back(candidate);
        }
        cached = choice;
    }
    return *cached;
}

}  // namespace toyhost
