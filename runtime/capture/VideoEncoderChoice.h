// VideoEncoderChoice: what `--codec auto` means. A hardware H.264 encoder (NVENC, VAAPI, QSV) is
// used when the ffmpeg found has one that works on this machine, checked by a short test encode
// the first time and remembered for the rest of the process; otherwise the software encoder with
// a throughput preset. No GL needed (runs ffmpeg).
#pragma once

#include <string>
#include <vector>

namespace toyhost {

struct VideoEncoderChoice {
    std::string codec;                 // the ffmpeg encoder name to use
    bool hardware = false;
    std::vector<std::string> tried;    // hardware encoders whose test encode failed
    // One line for the run's notices: "--codec auto: using h264_nvenc (hardware)" or why not.
    std::string explanation() const;
};

// The hardware encoders tried for H.264 containers, in order.
const std::vector<std::string>& hardwareH264Encoders();

// `container` is ".mp4", ".mov", ".mkv" or ".webm". WebM has no hardware candidate here
// (libvpx-vp9). Thread-safe; the test encodes run once per process.
VideoEncoderChoice chooseAutoVideoEncoder(const std::string& container);

}  // namespace toyhost
