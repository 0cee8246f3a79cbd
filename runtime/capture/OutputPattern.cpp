#include "capture/OutputPattern.h"

#include <algorithm>
#include <cctype>

namespace toyhost {

Result<OutputPattern> OutputPattern::parse(const std::string& pattern) {
    OutputPattern out;
    out.pattern_ = pattern;
    if (pattern == kRawStreamPattern) {
        out.prefix_ = pattern;
        for (const OutputKind& kind : outputKinds())
            if (!kind.toFile) out.kind_ = &kind;
        return out;
    }
    auto bad = [&](const std::string& why) { return Error("--out " + pattern + ": " + why, Code::UsageOut); };
    std::string* part = &out.prefix_;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') {
            *part += pattern[i];
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '%') {
            *part += '%';
            ++i;
            continue;
        }
        size_t j = i + 1;
        int width = 0;
        const bool zeroPad = j < pattern.size() && pattern[j] == '0';
        // Capped while reading: "%9999999999d" must not overflow int (it is refused below).
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])))
            width = std::min(width * 10 + (pattern[j++] - '0'), 1000);
        if (j >= pattern.size() || pattern[j] != 'd' || (width > 0 && !zeroPad) || width > 12)
            return bad("only %d or %0Nd (N <= 12) may stand for the frame number");
        if (out.width_ >= 0) return bad("the frame number may appear only once");
        out.width_ = width;
        part = &out.suffix_;
        i = j;
    }
    const std::string name = out.numbered() ? out.suffix_ : out.prefix_;
    const size_t dot = name.rfind('.');
    std::string ext = dot == std::string::npos || name.find('/', dot) != std::string::npos ? "" : name.substr(dot);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    out.extension_ = ext;
    const OutputKind* kind = outputKindOfExtension(ext);
    if (!kind) return bad("unsupported format \"" + ext + "\" (use " + outputKindsOffered() + ")");
    out.kind_ = kind;
    if (kind->oneFile() && out.numbered())
        return bad("a " + std::string(kind->name) + " is one file: remove the frame number placeholder");
    return out;
}

std::filesystem::path OutputPattern::pathFor(int frame) const {
    if (!numbered()) return prefix_;
    std::string digits = std::to_string(frame);
    if (static_cast<int>(digits.size()) < width_) digits.insert(0, width_ - digits.size(), '0');
    return prefix_ + digits + suffix_;
}

}  // namespace toyhost
