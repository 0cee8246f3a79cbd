// OutputSink: the one place a FrameSink is made for an output kind (capture/OutputKinds.h): image
// files, an ffmpeg video or the raw stream, with what a video's start says about its encoder. No
// GL needed.
#pragma once

#include <memory>
#include <string>

#include "capture/FrameSink.h"
#include "capture/OutputPattern.h"
#include "capture/VideoSink.h"
#include "core/Defaults.h"
#include "core/Result.h"
#include "image/ImageWriters.h"

namespace toyhost {

struct OutputSinkRequest {
    OutputPattern output;
    int width = 0, height = 0;    // the frames' size (a video's)
    int pngLevel = defaults::kPngLevel;
    ExrSettings exr;
    VideoSettings video;
    double fps = defaults::kFps;  // the video's frame rate
    int rawStreamFd = 1;          // where "--out -" writes (stdout)
};

struct OutputSink {
    std::unique_ptr<FrameSink> sink;
    // A video's ffmpeg encoder ("" otherwise), and with --codec auto why it was chosen.
    std::string videoEncoder, videoEncoderChoice;
};

// Makes the sink of `request.output`'s kind (a video: its command line and temporary names;
// ffmpeg itself starts with the first frame).
Result<OutputSink> makeOutputSink(const OutputSinkRequest& request);

}  // namespace toyhost
