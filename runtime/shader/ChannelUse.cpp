#include "shader/ChannelUse.h"

#include <cctype>
#include <string>

namespace toyhost {

namespace {
bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
}  // namespace

std::array<bool, kChannelCount> channelsNamed(std::string_view code) {
    std::array<bool, kChannelCount> named{};
    std::size_t i = 0;
    while (i < code.size()) {
        if (code.compare(i, 2, "//") == 0) {
            i = code.find('\n', i);
            if (i == std::string_view::npos) break;
            continue;
        }
        if (code.compare(i, 2, "/*") == 0) {
            i = code.find("*/", i + 2);
            if (i == std::string_view::npos) break;
            i += 2;
            continue;
        }
        if (!identifierChar(code[i])) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < code.size() && identifierChar(code[end])) ++end;
        const std::string_view word = code.substr(i, end - i);
        for (std::string_view prefix : {std::string_view("iChannel"), std::string_view("iCh")})
            if (word.size() == prefix.size() + 1 && word.substr(0, prefix.size()) == prefix && word.back() >= '0' &&
                word.back() < '0' + kChannelCount)
                named[word.back() - '0'] = true;
        i = end;
    }
    return named;
}

std::vector<Diagnostic> unboundChannelWarnings(const ManifestDesc& manifest) {
    std::vector<Diagnostic> warnings;
    for (const PassDesc& pass : manifest.passes) {
        const std::array<bool, kChannelCount> named = channelsNamed(pass.code);
        std::string list;
        int count = 0;
        for (int c = 0; c < kChannelCount; ++c) {
            if (!named[c] || pass.channels[c].kind != ChannelKind::None) continue;
            list += (count++ ? ", iChannel" : "iChannel") + std::to_string(c);
        }
        if (!count) continue;
        Diagnostic d;
        d.severity = Severity::Warning;
        d.code = Code::ChannelUnbound;
        d.file = pass.sourceName;
        d.pass = passName(pass.id);
        d.message = "the code samples " + list + (count == 1 ? ", which has" : ", which have") +
                    " nothing bound and read" + (count == 1 ? "s" : "") +
                    " as black (bind an input in the manifest's \"channels\")";
        warnings.push_back(std::move(d));
    }
    return warnings;
}

}  // namespace toyhost
