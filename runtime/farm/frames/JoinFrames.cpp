// JoinFrames: PNG frames, decoded one at a time, into VideoSink (see JoinFrames.h). No GL needed.
#include "farm/frames/JoinFrames.h"

#include <cctype>
#include <cstring>
#include <fstream>

#include "capture/CapturedFrame.h"
#include "capture/OutputKinds.h"
#include "core/AtomicFile.h"
#include "image/ImageFile.h"

namespace toyhost {

namespace {

// Whether `file` starts as one of the sound files `toyhost sound --out` writes does: WAV (RIFF
// WAVE), FLAC, Ogg (Vorbis, Opus), MP3 (an ID3 tag or an MPEG frame sync), M4A (an ISO "ftyp" box).
bool looksLikeSound(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    unsigned char b[12] = {};
    in.read(reinterpret_cast<char*>(b), sizeof b);
    if (in.gcount() < 12) return false;
    auto is = [&](std::size_t at, const char* text) { return std::memcmp(b + at, text, std::strlen(text)) == 0; };
    return (is(0, "RIFF") && is(8, "WAVE")) || is(0, "fLaC") || is(0, "OggS") || is(0, "ID3") ||
           (b[0] == 0xFF && (b[1] & 0xE0) == 0xE0) || is(4, "ftyp");
}

}  // namespace

Status joinFrames(const std::vector<std::filesystem::path>& frames, const std::filesystem::path& out, double fps,
                  const VideoSettings& settings, const std::function<bool()>& stopRequested) {
    if (frames.empty()) return Error("no frames to join", Code::Usage);
    // What ffmpeg would refuse only after every frame was decoded, refused first in toyhost's words.
    std::string ext = out.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const OutputKind* kind = outputKindOfExtension(ext);
    if (!kind || kind->format != OutputFormat::Video)
        return fileError(out.string(), "--out: expected a video file (" + extensionList(outputKind(OutputFormat::Video), ", ") + ")",
                         Code::Usage);
    if (settings.audio) {
        if (Status file = checkRegularFile(*settings.audio, "--audio"); !file) return file;
        if (!looksLikeSound(*settings.audio))
            return fileError(settings.audio->string(),
                             "--audio: not a sound file (expected one that `toyhost sound` writes: WAV, FLAC, Ogg/Opus, "
                             "MP3 or M4A)",
                             Code::Usage);
    }
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
        if (stopRequested && stopRequested()) {
            (*sink)->discard();
            return fileError(out.string(), "not written: stopped by a signal after " + std::to_string(i) + " of " +
                                               std::to_string(frames.size()) + " frames",
                             Code::Interrupted);
        }
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
