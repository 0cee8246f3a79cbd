#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "Commands.h"
#include "Console.h"
#include "NextCommand.h"
#include "core/AtomicFile.h"
#include "export/ShadertoyExport.h"
#include "image/ImageStats.h"
#include "image/ImageWriters.h"
#include "manifest/ManifestWriter.h"
#include "manifest/Starter.h"
#include "manifest/StockMedia.h"
#include "media/MediaResolver.h"
#include "core/Defaults.h"
#include "core/NumberText.h"
#include "export/LoadShadertoy.h"
#include "drivers/headless/HeadlessDriver.h"
#include "gl/GlThread.h"
#include <unistd.h>

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
              << "\n"
              << "toyhost: run it with: " << nextRunCommand(dir, shadertoy->runDefaults.frames.value_or(1)) << "\n";
    return kExitOk;
}

namespace {
bool hasExtension(const std::string& file, const char* extension) {
    std::string ext = std::filesystem::path(file).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == extension;
}

// A PNG or JPEG as floats holding its 8-bit levels.
Result<ImageF32> readLevels(const std::string& file) {
    Result<Image8> image = readPng(file);
    if (!image) return image.error();
    ImageF32 levels{image->width, image->height, std::vector<float>(image->rgba.begin(), image->rgba.end())};
    return levels;
}
}  // namespace

// `toyhost inspect`: one line per channel and file, for checking invariants of buffer dumps.
int inspectCommand(const std::vector<std::string>& files, const std::string& regionText) {
    Region region;
    if (!regionText.empty()) {
        const WholeNumbers read = wholeNumbersIn(regionText, ",", 4, 0, INT32_MAX);
        const std::vector<long long>& v = read.values;
        if (!read.problem.empty() || v[2] < 1 || v[3] < 1)
            return usage("--region " + regionText + ": expected X,Y,W,H (whole numbers, W and H at least 1)" +
                         (read.problem.empty() ? "" : ": " + read.problem));
        region = {static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]), static_cast<int>(v[3])};
    }
    for (const std::string& file : files) {
        // EXR dumps hold the raw floats; a PNG (what the screen shows) is read as 8-bit levels
        // 0..255, so its statistics are in levels and can never show NaN or Inf.
        const bool exr = hasExtension(file, ".exr");
        Result<ImageF32> image = exr ? readExr(file) : readLevels(file);
        if (!image) return fail(image.error());
        Result<std::array<ChannelStats, 4>> stats = channelStats(*image, region);
        if (!stats) return fail(inFile(file, stats.error()));
        std::printf("%s (%dx%d%s)\n", file.c_str(), image->width, image->height,
                    exr ? "" : ", 8-bit levels 0..255");
        const char* names = "RGBA";
        for (int c = 0; c < 4; ++c) {
            const ChannelStats& s = (*stats)[c];
            std::printf("  %c: sum %.9g mean %.9g min %.9g max %.9g nan %zu inf %zu\n", names[c], s.sum, s.mean, s.min,
                        s.max, s.nan, s.inf);
        }
    }
    return kExitOk;
}

// `toyhost new`: a starter folder that runs as it is.
int newCommand(const std::string& dir, const std::string& passes, bool force) {
    Result<StarterLayout> layout = parseStarterLayout(passes);
    if (!layout) return usage(layout.error().first().message);
    if (Status written = writeStarter(dir, *layout, force); !written) return fail(written.error());
    const ManifestDesc desc = starterManifest(dir, *layout);
    std::string files = desc.commonSource ? "common.glsl, " : "";
    for (const PassDesc& pass : desc.passes) files += passFileName(pass.id) + ", ";
    const char* slash = !dir.empty() && dir.back() == '/' ? "" : "/";
    std::cerr << "toyhost: wrote " << dir << slash << " (manifest.json, " << files << "README.md)\n"
              << "toyhost: run it with: " << nextRunCommand(dir, desc.runDefaults.frames.value_or(1)) << "\n";
    return kExitOk;
}

// `toyhost media`: the stock media table, and which real files the media folders hold.
int mediaCommand(const std::vector<std::string>& folders) {
    MediaResolver resolver;
    for (const std::string& folder : folders) resolver.addSearchFolder(folder);
    auto kindName = [](StockMediaKind kind) {
        switch (kind) {
            case StockMediaKind::Noise: return "noise";
            case StockMediaKind::Photo: return "photo";
            case StockMediaKind::Other: return "other";
        }
        return "other";
    };
    std::printf("%-18s %-6s %-10s %-3s %-6s %s\n", "NAME", "KIND", "SIZE", "CH", "FILE", "ID");
    for (const StockMediaInfo& info : stockMediaTable()) {
        const std::string size = std::to_string(info.width) + "x" + std::to_string(info.height);
        const std::optional<std::filesystem::path> file = resolver.findFile(stockMediaPath(info));
        std::printf("%-18s %-6s %-10s %-3d %-6s %s\n", std::string(info.name).c_str(), kindName(info.kind),
                    size.c_str(), info.channels, file ? "found" : "-", stockMediaPath(info).c_str());
    }
    // Cubemaps, volumes, videos and music: a cubemap is found by its face 0 file (its other faces
    // are <hash>_1 .. <hash>_5 beside it).
    std::printf("\n%-28s %-8s %-10s %-3s %-6s %s\n", "NAME", "KIND", "SIZE", "CH", "FILE", "ID");
    for (const StockInputInfo& info : stockInputTable()) {
        const std::string size = info.form == StockInputForm::Volume ? std::to_string(info.size) + "^3"
                                 : info.form == StockInputForm::Cubemap ? "6 faces"
                                                                        : "-";
        const std::optional<std::filesystem::path> file = resolver.findFile(stockInputPath(info));
        std::printf("%-28s %-8s %-10s %-3d %-6s %s\n", std::string(info.name).c_str(), stockInputFormName(info.form),
                    size.c_str(), info.channels, file ? "found" : "-", stockInputPath(info).c_str());
    }
    std::printf("\nBind one by name or id: \"iChannel0\": {\"media\": \"Abstract 3\"}. Without a real file (FILE -) a\n"
                "deterministic stand-in of the same size and channels is used (cubemaps: a sky, volumes: noise,\n"
                "videos: a moving pattern, music: the spectrum the site shows without audio); give the file with\n"
                "--media DIR, $TOYHOST_MEDIA or --media-file ID=FILE.\n");
    if (!folders.empty()) {
        std::printf("Searched:");
        for (const std::string& folder : folders) std::printf(" %s", folder.c_str());
        std::printf("\n");
    }
    return kExitOk;
}

}  // namespace toyhost::cli

namespace toyhost::cli {

// `toyhost sound`: the Sound pass rendered up front as the site does, written as audio, through a
// SessionCore like every run (signals, the watchdog, an all-or-nothing output file).
int soundCommand(const SoundCommandOptions& o, const GlProcess& process) {
    SessionOptions options;
    options.target = o.target;
    options.sound = SoundRequest{o.out, o.seconds};
    options.eglPlatform = process.eglPlatform;
    options.startedAt = process.startedAt;
    // A runaway mainSound is ended like a runaway frame (each block of samples is one draw).
    options.settings.frameTimeout = defaults::kFrameTimeoutSeconds;
    if (Status given = o.flags.applyTo(options.settings, options.mouse); !given) return fail(given.error());
    if (o.out == "-" && process.closedAtStart[STDOUT_FILENO])
        return usage("--out -: stdout is closed; give it a file or a pipe (or --out music.wav)");
    if (o.out == "-" && isatty(STDOUT_FILENO))
        return usage("--out -: stdout is a terminal; redirect the WAV stream to a file or a pipe");
    int code = kExitOk;
    runOnGlThread([&] { code = runSession(options, o.quiet, runHeadless); });
    return code;
}

}  // namespace toyhost::cli
