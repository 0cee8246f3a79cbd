// The sinks that need no helper process: one image file per frame (PNG or EXR, written in
// parallel, each complete or absent) and the raw RGBA8 stream on a file descriptor (stdout).
// CPU only, no GL needed.
#pragma once

#include <filesystem>
#include <mutex>
#include <set>

#include "capture/FrameSink.h"
#include "capture/OutputPattern.h"
#include "core/FileDescriptor.h"

namespace toyhost {

class ImageSequenceSink final : public FrameSink {
public:
    // `pngLevel`: --png-level 0..9 for PNG files; `exr`: how EXR files are stored.
    ImageSequenceSink(OutputPattern pattern, int pngLevel, ExrSettings exr = {})
        : pattern_(std::move(pattern)), pngLevel_(pngLevel), exr_(exr) {}
    bool ordered() const override { return false; }
    Status write(const CapturedFrame& frame, EncodeScratch& scratch) override;

private:
    // Creates the folder of `path` the first time a frame goes there; after that the folder must
    // still exist (one that vanishes mid-run ends the run instead of being made again with only
    // the later frames). Frames are written in parallel: the creation is done under the lock, so
    // no frame is written into a folder another thread has yet to make.
    Status makeFolderOnce(const std::filesystem::path& path);

    OutputPattern pattern_;
    int pngLevel_;
    ExrSettings exr_;
    std::mutex foldersMutex_;
    std::set<std::filesystem::path> folders_;  // created (or found) for an earlier frame
};

// The raw stream format: per frame width * height * 4 bytes, RGBA8, rows top first (like image
// files), no header and nothing between frames; a buffer capture is clamped to 8 bits.
class RawStreamSink final : public FrameSink {
public:
    // Does not own `fd`. `name` says what it is in error messages ("stdout").
    RawStreamSink(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}
    bool ordered() const override { return true; }
    Status write(const CapturedFrame& frame, EncodeScratch& scratch) override;
    void cancel() override { cancel_.cancel(); }

private:
    int fd_;
    std::string name_;
    CancelSignal cancel_;
};

}  // namespace toyhost
