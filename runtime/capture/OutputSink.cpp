#include "capture/OutputSink.h"

#include "capture/FileSinks.h"

namespace toyhost {

Result<OutputSink> makeOutputSink(const OutputSinkRequest& r) {
    OutputSink made;
    switch (r.output.format()) {
        case OutputFormat::Png:
        case OutputFormat::Exr:
            made.sink = std::make_unique<ImageSequenceSink>(r.output, r.pngLevel, r.exr);
            break;
        case OutputFormat::RawStream:
            made.sink = std::make_unique<RawStreamSink>(r.rawStreamFd, "stdout");
            break;
        case OutputFormat::Video: {
            Result<std::unique_ptr<VideoSink>> video =
                VideoSink::start(r.output.pathFor(0), r.width, r.height, r.fps, r.video);
            if (!video) return video.error();
            made.videoEncoder = (*video)->encoder();
            made.videoEncoderChoice = (*video)->autoExplanation();
            made.sink = std::move(*video);
            break;
        }
    }
    return made;
}

}  // namespace toyhost
