// JoinFrames: PNG frames, decoded one at a time, into VideoSink (see JoinFrames.h). No GL needed.
#include "farm/frames/JoinFrames.h"

#include <cstring>

#include "capture/CapturedFrame.h"
#include "image/ImageFile.h"

namespace toyhost {

Status joinFrames(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& out, double fps,
                  const VideoSettings& settings) {
    if (frames.empty()) return Error("no frames to join", Code::Usage);
    for (const auto& frame : frames)
        if (frame.extension() != ".png")
            return fileError(frame.string(),
                             "farm join encodes PNG frames (EXR frames hold floats: choose their tone mapping, then "
                             "encode with ffmpeg)",
                             Code::Usage);
    Result<Image8> first = loadImageFile(frames.front());
    if (!first) return first.error();
    Result<std::unique_ptr<VideoSink>> sink = VideoSink::start(out, first->width, first->height, fps, settings);
    if (!sink) return sink.error();
    EncodeScratch scratch;
    CapturedFrame captured;
    captured.width = first->width;
    captured.height = first->height;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        Result<Image8> image = i == 0 ? std::move(first) : loadImageFile(frames[i]);
        if (!image) {
            (*sink)->discard();
            return image.error();
        }
        if (image->width != captured.width || image->height != captured.height) {
            (*sink)->discard();
            return fileError(frames[i].string(),
                             std::to_string(image->width) + "x" + std::to_string(image->height) + ", but the first frame is " +
                                 std::to_string(captured.width) + "x" + std::to_string(captured.height),
                             Code::Usage);
        }
        captured.frame = static_cast<int>(i);
        captured.pixels.resize(image->rgba.size());
        std::memcpy(captured.pixels.data(), image->rgba.data(), image->rgba.size());
        if (Status written = (*sink)->write(captured, scratch); !written) {
            (*sink)->discard();
            return written;
        }
    }
    if (Status closed = (*sink)->close(); !closed) {
        (*sink)->discard();
        return closed;
    }
    return okStatus();
}

}  // namespace toyhost
