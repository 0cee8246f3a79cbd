#include "SessionFlags.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "Commands.h"
#include "NumberOptions.h"
#include "core/Defaults.h"
#include "core/NumberText.h"

namespace toyhost::cli {

namespace {

// The settings the library's errors name, and the flags that set them.
constexpr std::pair<const char*, const char*> kFlagOfSetting[] = {
    {"size", "--size"},
    {"frames", "--frames"},
    {"fps", "--fps"},
    {"start_time", "--start-time"},
    {"date", "--date"},
    {"mouse", "--mouse"},
    {"frame_timeout", "--frame-timeout"},
    {"compile_timeout", "--compile-timeout"},
    {"supersample", "--supersample"},
    {"motion_blur", "--motion-blur"},
    {"shutter", "--shutter"},
    {"dither", "--dither"},
    {"shutter_offset", "--shutter-offset"},
    {"sample_space", "--sample-space"},
    {"tile", "--tile"},
    {"seconds", "--seconds"},
    {"defines", "--define"},
};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

Error usageError(std::string message) { return Error(std::move(message), Code::Usage); }

}  // namespace

Error withFlagNames(Error error) {
    for (Diagnostic& d : error.diagnostics)
        for (const auto& [setting, flag] : kFlagOfSetting)
            if (d.field == setting) d.field = flag;
    return error;
}

void SessionFlags::define(CLI::App& command, unsigned groups) {
    const CLI::Validator timeoutSeconds = timeoutSecondsOption();
    if (groups & Canvas)
        command.add_option("--size", size_,
                           "Canvas size WxH (default: the manifest's \"defaults\", else " +
                               std::to_string(defaults::kCanvasWidth) + "x" + std::to_string(defaults::kCanvasHeight) + ")");
    if (groups & Clock) {
        command.add_option("--fps", fps_,
                           "Fixed time step: frame n has iTime = start + n/F, iTimeDelta = 1/F (default: the "
                           "manifest's, else " + number(defaults::kFps) + "; in a window: real time)");
        command.add_option("--start-time", startTime_, "iTime of frame 0, in seconds (default 0)");
        command.add_option("--date", date_, "iDate at frame 0, YYYY-MM-DDTHH:MM:SS (default: now, local time)");
    }
    if (groups & Input) {
        command.add_option("--mouse", mouse_, "Press the button at pixel X,Y (origin bottom-left) on frame 0 and hold it");
        command.add_option("--mouse-script", mouseScript_, "JSON list of timed mouse events (see docs/input.md)");
        command.add_option("--key-script", keyScript_, "JSON list of timed key events (see docs/input.md)");
    }
    if (groups & Media) {
        command.add_option("--media", mediaFolders_,
                           "Folder with real stock media files, by hash or name (repeatable; also $TOYHOST_MEDIA)");
        command.add_option("--media-file", mediaFiles_, "Use FILE for a stock media id: ID=FILE (repeatable)");
    }
    if (groups & Limits) {
        command.add_option("--frame-timeout", frameTimeout_,
                           "Watchdog: end the run (exit 124) when one pass of a frame draws for longer than this many "
                           "seconds, or the encoders take no frame for that long (default " +
                               number(defaults::kFrameTimeoutSeconds) + " headless, off in a window; 0: off; else at least " +
                               number(defaults::kMinTimeoutSeconds) + ")")
            ->check(timeoutSeconds);
        command.add_option("--compile-timeout", compileTimeout_,
                           "Watchdog: end the run (exit 124) when compiling one pass takes longer than this many "
                           "seconds (default " + number(defaults::kCompileTimeoutSeconds) + "; 0: off; else at least " +
                               number(defaults::kMinTimeoutSeconds) + ")")
            ->check(timeoutSeconds);
    }
    if (groups & Shader)
        command.add_option("--define", defines_,
                           "Add #define NAME VALUE to every pass, after the site's header and before Common: NAME "
                           "(defined as 1) or NAME=VALUE (repeatable)")
            ->allow_extra_args(false);
}

Status SessionFlags::parseMouse(std::optional<glm::vec2>& mouse) const {
    if (mouse_.empty()) return okStatus();
    // Decimal numbers as every number is read (no 0x1p4, inf or nan), finite as floats.
    const std::size_t comma = mouse_.find(',');
    const std::optional<double> x = comma == std::string::npos ? std::nullopt : parseDecimalNumber(mouse_.substr(0, comma));
    const std::optional<double> y = comma == std::string::npos ? std::nullopt : parseDecimalNumber(mouse_.substr(comma + 1));
    if (!x || !y || !std::isfinite(static_cast<float>(*x)) || !std::isfinite(static_cast<float>(*y)))
        return usageError("--mouse " + mouse_ + ": expected X,Y in pixels");
    mouse = glm::vec2(static_cast<float>(*x), static_cast<float>(*y));
    return okStatus();
}

Status SessionFlags::parseMedia(std::vector<std::filesystem::path>& folders,
                                std::vector<std::pair<std::string, std::filesystem::path>>& files) const {
    for (const std::string& entry : mediaFiles_) {
        const std::size_t eq = entry.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == entry.size())
            return usageError("--media-file " + entry + ": expected ID=FILE");
        files.emplace_back(entry.substr(0, eq), entry.substr(eq + 1));
    }
    for (const std::string& folder : mediaFolders_) folders.emplace_back(folder);
    if (const char* folder = std::getenv("TOYHOST_MEDIA"); folder && *folder) folders.emplace_back(folder);
    return okStatus();
}

Status SessionFlags::applyTo(SessionSettings& s, std::optional<glm::vec2>& mouse) const {
    // Only what was given is set, as given: the library checks it (prepareSession, once for every
    // session) and names the setting in its errors, which withFlagNames shows as the flag.
    if (!size_.empty()) {
        // Whole numbers as every number is read: 4294967396x100 is refused, not wrapped to 100x100.
        const WholeNumbers size = wholeNumbersIn(size_, "xX", 2, INT32_MIN, INT32_MAX);
        if (!size.problem.empty()) return usageError("--size " + size_ + ": expected WxH, e.g. 800x450: " + size.problem);
        s.width = static_cast<int>(size.values[0]);
        s.height = static_cast<int>(size.values[1]);
    }
    if (fps_) s.fps = *fps_;
    if (startTime_) s.startTime = *startTime_;
    if (!date_.empty()) s.date = date_;
    if (Status parsed = parseMouse(mouse); !parsed) return parsed;
    if (!mouseScript_.empty()) s.mouseScript = mouseScript_;
    if (!keyScript_.empty()) s.keyScript = keyScript_;
    if (frameTimeout_) s.frameTimeout = *frameTimeout_;
    if (compileTimeout_) s.compileTimeout = *compileTimeout_;
    s.defines = defines_;
    return parseMedia(s.mediaFolders, s.mediaFiles);
}

}  // namespace toyhost::cli
