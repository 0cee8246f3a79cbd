// OutputKinds: the one table of what `--out` can write (PNG and EXR files, a video through ffmpeg,
// raw frames on stdout), one row per kind with every fact the session, the recorder and the sinks
// decide by. Pure data; no GL needed.
#pragma once

#include <span>
#include <string>

namespace toyhost {

enum class OutputFormat { Png, Exr, Video, RawStream };

struct OutputKind {
    OutputFormat format;
    const char* name;                         // as messages say it ("the unfinished video")
    std::span<const char* const> extensions;  // lower case with the dot; none for the raw stream
    bool toFile = true;        // false: the raw stream, written to stdout ("-")
    bool streamed = false;     // every captured frame goes into one output, in frame order
    bool floats = false;       // takes the float readback as it is (the Image pass is rendered in float)
    bool exrSettings = false;  // --exr-compression and --exr-half apply
    bool tiles = false;        // a tiled canvas can be written band by band
    bool ffmpeg = false;       // encoded by an ffmpeg child (--codec, --video-quality, --video-preset apply)
    bool fixedRate = false;    // plays at one frame rate: a recording from a window needs --fps
    bool soundTrack = false;   // carries the Sound pass

    // One file per captured frame (numbered by a placeholder), one file for all, or none (stdout).
    bool filePerFrame() const { return toFile && !streamed; }
    bool oneFile() const { return toFile && streamed; }
};

// The "--out" pattern that means the raw stream.
inline constexpr const char* kRawStreamPattern = "-";

// Every kind, in the order usage messages list them.
std::span<const OutputKind> outputKinds();
const OutputKind& outputKind(OutputFormat format);
// The file kind with lower-case extension `ext` (".mp4"), or nullptr.
const OutputKind* outputKindOfExtension(const std::string& ext);
// `kind`'s extensions joined by `separator` (".mp4, .webm, .mov, .mkv").
std::string extensionList(const OutputKind& kind, const char* separator);
// The extensions of every kind that has `fact`, joined by ", " (&OutputKind::soundTrack: ".mp4,
// .webm, .mov, .mkv").
std::string extensionsWhere(bool OutputKind::*fact);
// The names of the kinds a tiled canvas can be written as, joined by " or " ("PNG or EXR").
std::string tiledKindNames();
// What `--out` accepts, for the message refusing an extension (".png, .exr, a video
// .mp4/.webm/.mov/.mkv, or - for raw RGBA on stdout").
std::string outputKindsOffered();

}  // namespace toyhost
