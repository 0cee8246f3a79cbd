// OutputPattern: the `--out` argument. Expands a printf-style frame number ("%04d") and picks the
// output kind from the extension: image files per frame, one video file, or "-" for raw frames on
// stdout. Pure string logic; no GL needed.
#pragma once

#include <filesystem>
#include <string>

#include "capture/OutputKinds.h"
#include "core/Result.h"

namespace toyhost {

class OutputPattern {
public:
    // Accepts "%d", "%0Nd" (one of them at most) and "%%"; the extension must be one of a file
    // kind's (capture/OutputKinds.h; no placeholder for a kind that is one file); "-" alone is
    // the raw stream.
    static Result<OutputPattern> parse(const std::string& pattern);

    // The kind's row of capture/OutputKinds.h: every fact that depends on what is written.
    const OutputKind& kind() const { return *kind_; }
    OutputFormat format() const { return kind_->format; }
    bool numbered() const { return width_ >= 0; }
    // True when every captured frame goes into one output (a video or the raw stream).
    bool streamed() const { return kind_->streamed; }
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
    const OutputKind* kind_ = &outputKinds().front();
};

}  // namespace toyhost
