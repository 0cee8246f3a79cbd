#include <cstdio>
#include <iostream>

#include "Commands.h"
#include "Console.h"
#include "core/AtomicFile.h"
#include "export/ShadertoyExport.h"
#include "image/ImageStats.h"
#include "image/ImageWriters.h"
#include "manifest/ManifestWriter.h"

namespace toyhost::cli {

// `toyhost import`: the export's passes as files, byte for byte, with a manifest binding them.
int importCommand(const std::string& source, const std::string& dir, bool force) {
    Result<std::string> text = readTextFile(source);
    if (!text) return fail(text.error());
    Result<ManifestDesc> shadertoy = parseShadertoyExport(*text, source);
    if (!shadertoy) return fail(shadertoy.error());
    for (const Diagnostic& notice : shadertoy->notices) printDiagnostic(notice);
    if (Status written = writeManifestFolder(*shadertoy, dir, force); !written) return fail(written.error());
    std::cerr << "toyhost: imported " << shadertoy->name << " into " << dir << " (" << shadertoy->passes.size()
              << (shadertoy->passes.size() == 1 ? " pass" : " passes") << (shadertoy->commonSource ? " + Common)" : ")")
              << "\n";
    return kExitOk;
}

// `toyhost inspect`: one line per channel and file, for checking invariants of buffer dumps.
int inspectCommand(const std::vector<std::string>& files, const std::string& regionText) {
    Region region;
    if (!regionText.empty()) {
        char extra = 0;
        long long x, y, w, h;
        if (std::sscanf(regionText.c_str(), "%lld,%lld,%lld,%lld%c", &x, &y, &w, &h, &extra) != 4 || x < 0 || y < 0 ||
            w < 0 || h < 0 || x > INT32_MAX || y > INT32_MAX || w > INT32_MAX || h > INT32_MAX)
            return usage("--region " + regionText + ": expected X,Y,W,H (non-negative whole numbers)");
        region = {static_cast<int>(x), static_cast<int>(y), static_cast<int>(w), static_cast<int>(h)};
    }
    for (const std::string& file : files) {
        Result<ImageF32> image = readExr(file);
        if (!image) return fail(image.error());
        Result<std::array<ChannelStats, 4>> stats = channelStats(*image, region);
        if (!stats) return fail(inFile(file, stats.error()));
        std::printf("%s (%dx%d)\n", file.c_str(), image->width, image->height);
        const char* names = "RGBA";
        for (int c = 0; c < 4; ++c) {
            const ChannelStats& s = (*stats)[c];
            std::printf("  %c: sum %.9g mean %.9g min %.9g max %.9g nan %zu inf %zu\n", names[c], s.sum, s.mean, s.min,
                        s.max, s.nan, s.inf);
        }
    }
    return kExitOk;
}

}  // namespace toyhost::cli
