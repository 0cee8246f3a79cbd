// OutputPattern: the `--out` argument. Expands a printf-style frame number ("%04d") and picks the
// output kind from the extension: image files per frame, one video file, or "-" for raw frames on
// stdout. Pure string logic; no GL needed.
#pragma once

#include <filesystem>
#include <string>

#include "core/Result.h"

namespace toyhost {

// Png/Exr: one file per captured frame. Video: one file encoded by ffmpeg (.mp4, .webm, .mov,
// .mkv). RawStream: "-", every captured frame's RGBA8 bytes on stdout.
enum class OutputFormat { Png, Exr, Video, RawStream };

class OutputPattern {
public:
    // Accepts "%d", "%0Nd" (one of them at most) and "%%"; the extension must be .png or .exr,
    // or a video container (no placeholder: a video is one file); "-" alone is the raw stream.
    static Result<OutputPattern> parse(const std::string& pattern);

    OutputFormat format() const { return format_; }
    bool numbered() const { return width_ >= 0; }
    // True when every captured frame goes into one output (a video or the raw stream).
    bool streamed() const { return format_ == OutputFormat::Video || format_ == OutputFormat::RawStream; }
    // Lower-case extension with its dot (".mp4"); empty for the raw stream.
    const std::string& extension() const { return extension_; }
    std::filesystem::path pathFor(int frame) const;
    const std::string& text() const { return pattern_; }

private:
    std::string pattern_;
    std::string prefix_;
    std::string suffix_;
    std::string extension_;
    int width_ = -1;  // -1: no placeholder
    OutputFormat format_ = OutputFormat::Png;
};

}  // namespace toyhost
