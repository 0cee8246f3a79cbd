#include "capture/FileSinks.h"

#include <filesystem>

#include "capture/FrameBytes.h"
#include "image/ImageWriters.h"

namespace toyhost {

Status ImageSequenceSink::makeFolderOnce(const std::filesystem::path& path) {
    const std::filesystem::path folder = path.parent_path();
    if (folder.empty()) return okStatus();
    const std::lock_guard<std::mutex> lock(foldersMutex_);
    if (folders_.contains(folder)) return okStatus();
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) return fileError(folder.string(), "cannot create folder: " + ec.message(), Code::IoWrite);
    folders_.insert(folder);
    return okStatus();
}

Status ImageSequenceSink::write(const CapturedFrame& frame, EncodeScratch& scratch) {
    const std::filesystem::path path = pattern_.pathFor(frame.frame);
    if (Status folder = makeFolderOnce(path); !folder) return folder;
    constexpr ParentFolders parents = ParentFolders::MustExist;
    Status written = okStatus();
    scratch.image.encodeSeconds = scratch.image.writeSeconds = 0;  // a file refused early took none
    if (pattern_.kind().floats) {
        if (frame.format != PixelFormat::Rgba32f)
            return fileError(path.string(), "EXR capture needs a float readback", Code::CaptureFormat);
        written = writeExr(path, frame.width, frame.height, frame.rgba32f(), &scratch.image, exr_, parents);
    } else {
        written = writePng(path, frame.width, frame.height, rgba8BottomUp(frame, scratch.bytes), pngLevel_,
                           &scratch.image, parents);
    }
    encodeNanos(scratch.image.encodeSeconds);
    writeNanos(scratch.image.writeSeconds);
    if (!written) return written;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec) addBytesWritten(size);
    return okStatus();
}

Status RawStreamSink::write(const CapturedFrame& frame, EncodeScratch& scratch) {
    Clock::time_point at = Clock::now();
    const std::span<const std::uint8_t> topFirst =
        rowsTopFirst(rgba8BottomUp(frame, scratch.bytes), frame.width, frame.height, scratch.rows);
    at = addEncodeTime(at);
    Status written = writeAll(fd_, std::as_bytes(topFirst), name_, &cancel_);
    addWriteTime(at);
    if (!written) return written;
    addBytesWritten(topFirst.size());
    return okStatus();
}

}  // namespace toyhost
