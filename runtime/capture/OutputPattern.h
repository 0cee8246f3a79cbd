// OutputPattern: the `--out` argument. Expands a printf-style frame number ("%04d") and picks the
// file format from the extension. Pure string logic; no GL needed.
#pragma once

#include <filesystem>
#include <string>

#include "core/Result.h"

namespace toyhost {

enum class OutputFormat { Png, Exr };

class OutputPattern {
public:
    // Accepts "%d", "%0Nd" (one of them at most) and "%%"; the extension must be .png or .exr.
    static Result<OutputPattern> parse(const std::string& pattern);

    OutputFormat format() const { return format_; }
    bool numbered() const { return width_ >= 0; }
    std::filesystem::path pathFor(int frame) const;
    const std::string& text() const { return pattern_; }

private:
    std::string pattern_;
    std::string prefix_;
    std::string suffix_;
    int width_ = -1;  // -1: no placeholder
    OutputFormat format_ = OutputFormat::Png;
};

}  // namespace toyhost
