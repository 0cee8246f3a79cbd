// `toyhost compare A B`: two shadertoys rendered with the same inputs (compareShadertoys,
// include/toyhost/Compare.h) and the answer printed as a per-frame table or JSON. Difference images
// and frames are written by a BackgroundWriter, never on the GL thread, each file complete or
// absent. Exit 0 equal within the tolerance, 1 different, 2 when no answer could be given.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <toyhost/Compare.h>

#include "Commands.h"
#include "Console.h"
#include "core/Defaults.h"
#include "image/ImageWriters.h"
#include "session/BackgroundWriter.h"
#include "session/SettingChecks.h"
#include "session/StopSignals.h"

namespace toyhost::cli {

namespace {

namespace fs = std::filesystem;

// Compare's own exit codes follow cmp(1) and diff(1): 1 is "they differ", so every failure that
// prevents an answer is 2 (a watchdog expiry or a signal keeps its usual code).
constexpr int kExitDiffer = 1;
constexpr int kExitTrouble = 2;

int trouble(const Error& error) {
    const int code = fail(error);
    return code == kExitFailure ? kExitTrouble : code;
}

std::string frameFile(const std::string& dir, const char* prefix, int frame) {
    char name[64];
    std::snprintf(name, sizeof name, "%s_%04d.png", prefix, frame);
    return (fs::path(dir) / name).string();
}

std::string psnrText(double psnr) {
    if (std::isinf(psnr)) return "inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", psnr);
    return text;
}

// Writes rows given top first as a PNG (writePng takes them bottom first), on the writer's thread.
BackgroundWriter::Job pngJob(std::string path, int width, int height, std::span<const std::uint8_t> topFirst) {
    std::vector<std::uint8_t> rows(topFirst.begin(), topFirst.end());
    return [path = std::move(path), width, height, rows = std::move(rows)]() mutable -> Result<fs::path> {
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        for (int y = 0; y < height / 2; ++y)
            std::swap_ranges(rows.begin() + static_cast<std::ptrdiff_t>(y * row),
                             rows.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                             rows.begin() + static_cast<std::ptrdiff_t>((height - 1 - y) * row));
        if (Status written = writePng(path, width, height, rows); !written) return written.error();
        return fs::path(path);
    };
}

// The files asked for, written off the GL thread with at most a few frames waiting (the renderer
// waits for the writer beyond that, so memory stays bounded).
class CompareFiles {
public:
    CompareFiles(std::string diffOut, std::string framesOut)
        : diffOut_(std::move(diffOut)), framesOut_(std::move(framesOut)) {}
    bool any() const { return !diffOut_.empty() || !framesOut_.empty(); }
    bool wantsDiff() const { return !diffOut_.empty(); }

    Status prepare() {
        for (const std::string& dir : {diffOut_, framesOut_}) {
            if (dir.empty()) continue;
            std::error_code ec;
            fs::create_directories(dir, ec);
            if (ec || !fs::is_directory(dir)) return fileError(dir, "cannot create the folder: " + ec.message(), Code::IoWrite);
        }
        return okStatus();
    }
    // Queues the frame's files; false when a write failed (the error is kept).
    bool add(const ComparedFrame& f, int width, int height) {
        const int n = f.difference.frame;
        if (!f.diffImage.empty()) submit(pngJob(frameFile(diffOut_, "diff", n), width, height, f.diffImage), &diffs_);
        if (!framesOut_.empty()) {
            submit(pngJob(frameFile(framesOut_, "a", n), width, height, f.a), &frames_);
            submit(pngJob(frameFile(framesOut_, "b", n), width, height, f.b), &frames_);
        }
        if (submitted_ - collected_ > kMaxWaiting) writer_.drain();
        collect();
        return !error_;
    }
    // Waits for every file; the first write error, if any.
    Status finish() {
        writer_.drain();
        collect();
        if (error_) return *error_;
        return okStatus();
    }
    const std::vector<std::string>& diffs() const { return diffs_; }
    const std::vector<std::string>& frames() const { return frames_; }

private:
    static constexpr int kMaxWaiting = 8;
    void submit(BackgroundWriter::Job job, std::vector<std::string>* list) {
        ++submitted_;
        lists_.push_back(list);
        writer_.submit(std::move(job));
    }
    void collect() {
        for (Result<fs::path>& done : writer_.takeFinished()) {
            std::vector<std::string>* list = lists_[static_cast<std::size_t>(collected_++)];
            if (done) list->push_back(done->string());
            else if (!error_) error_ = done.error();
        }
    }

    std::string diffOut_, framesOut_;
    BackgroundWriter writer_;
    std::vector<std::vector<std::string>*> lists_;  // where each submitted job's file is listed
    long long submitted_ = 0, collected_ = 0;
    std::vector<std::string> diffs_, frames_;
    std::optional<Error> error_;
};

void printTable(const CompareReport& report) {
    std::printf("%6s %10s %9s %9s %10s %10s  %s\n", "frame", "iTime", "PSNR dB", "max diff", "mean diff", "pixels",
                "first differing pixel (x, y from the top left)");
    for (const FrameDifference& f : report.frames) {
        std::string first = "-";
        if (f.firstX >= 0) first = "(" + std::to_string(f.firstX) + ", " + std::to_string(f.firstY) + ")";
        std::printf("%6d %10.4f %9s %9d %10.4f %10lld  %s%s\n", f.frame, f.time, psnrText(f.psnr).c_str(), f.maxDiff,
                    f.meanDiff, static_cast<long long>(f.differingPixels), first.c_str(),
                    f.withinTolerance ? "" : "  differs");
    }
}

std::string summary(const CompareReport& report, const CompareTolerance& tolerance) {
    const std::size_t total = report.frames.size();
    std::string text;
    if (report.equal()) {
        text = "equal: " + std::to_string(total) + (total == 1 ? " frame" : " frames") + " of " + report.pass + " at " +
               std::to_string(report.width) + "x" + std::to_string(report.height);
        if (std::isinf(report.minPsnr)) return text + ", identical (PSNR inf)";
        return text + " within the tolerance (worst PSNR " + psnrText(report.minPsnr) + " dB, max diff " +
               std::to_string(report.maxDiff) + ")";
    }
    std::size_t differing = 0;
    for (const FrameDifference& f : report.frames) differing += f.withinTolerance ? 0 : 1;
    const FrameDifference& first = report.frames[static_cast<std::size_t>(*report.firstDifferingFrame)];
    char time[32];
    std::snprintf(time, sizeof time, "%g", first.time);
    text = "differ: first at frame " + std::to_string(first.frame) + " (iTime " + time + ")";
    if (first.firstX >= 0)
        text += ", pixel (" + std::to_string(first.firstX) + ", " + std::to_string(first.firstY) + ") from the top left";
    text += "; " + std::to_string(differing) + " of " + std::to_string(total) + " frames differ";
    if (!tolerance.minPsnr && !tolerance.maxDiff) text += " (no tolerance given: only identical frames are equal)";
    return text + "; worst PSNR " + psnrText(report.minPsnr) + " dB, max diff " + std::to_string(report.maxDiff);
}

nlohmann::ordered_json toJson(const CompareReport& report, const std::string& a, const std::string& b,
                      const CompareTolerance& tolerance, const CompareFiles& files) {
    using json = nlohmann::ordered_json;
    // JSON has no infinity: a PSNR of identical frames is null.
    auto psnr = [](double value) { return std::isinf(value) ? json(nullptr) : json(value); };
    json frames = json::array();
    for (const FrameDifference& f : report.frames) {
        json frame = {{"frame", f.frame},          {"time", f.time},
                      {"psnr", psnr(f.psnr)},      {"max_diff", f.maxDiff},
                      {"mean_diff", f.meanDiff},   {"differing_pixels", f.differingPixels},
                      {"equal", f.withinTolerance}};
        frame["first_differing_pixel"] =
            f.firstX >= 0 ? json{{"x", f.firstX}, {"y", f.firstY}} : json(nullptr);
        frames.push_back(std::move(frame));
    }
    json out = {{"a", a}, {"b", b}, {"pass", report.pass}, {"width", report.width}, {"height", report.height},
                {"fps", report.fps}, {"start_time", report.startTime},
                {"equal", report.equal()}, {"min_psnr", psnr(report.minPsnr)},
                {"max_diff", report.maxDiff}};
    out["tolerance"] = {{"psnr", tolerance.minPsnr ? json(*tolerance.minPsnr) : json(nullptr)},
                        {"max_diff", tolerance.maxDiff ? json(*tolerance.maxDiff) : json(nullptr)}};
    out["first_differing_frame"] = report.firstDifferingFrame ? json(*report.firstDifferingFrame) : json(nullptr);
    out["frames"] = std::move(frames);
    out["diff_images"] = files.diffs();
    out["frame_images"] = files.frames();
    return out;
}

}  // namespace

void CompareCommand::define(CLI::App& compare) {
    compare.add_option("a", a_, "The first shadertoy (folder, manifest or Shadertoy JSON export): the reference")->required();
    compare.add_option("b", b_, "The second shadertoy, rendered with the same settings and inputs")->required();
    flags_.define(compare, SessionFlags::All);
    sampling_.define(compare);
    compare.add_option("--frames", frames_,
                       "Frames to render and compare (default: A's manifest defaults, else " +
                           std::to_string(defaults::kCompareFrames) + ")");
    compare.add_option("--pass", pass_,
                       "Pass to compare: Image (default; R, G, B) or \"Buffer A\" .. \"Buffer D\" (or A..D; R, G, B, A "
                       "as 8-bit levels)");
    compare.add_option("--tolerance-psnr", tolerancePsnr_,
                       "Frames are equal when their PSNR is at least this many dB (default: only identical frames)");
    compare.add_option("--max-diff", maxDiff_,
                       "Frames are equal when no sample differs by more than L levels (0..255); pixels within it "
                       "do not count as differing");
    compare.add_option("--diff-out", diffOut_,
                       "Write a difference image of each frame that differs: DIR/diff_NNNN.png (|A - B| x " +
                           std::to_string(defaults::kCompareDiffGain) + " per channel, numbered by iFrame)");
    compare.add_option("--frames-out", framesOut_, "Write both frames of every compared frame: DIR/a_NNNN.png, DIR/b_NNNN.png");
    compare.add_flag("--json", json_, "Print the report as JSON on stdout instead of the table (a PSNR of identical frames is null)");
}

int CompareCommand::execute(const GlProcess&) {
    CompareSettings settings;
    SessionSettings& s = settings.session;
    std::optional<glm::vec2> mouse;
    if (Status given = flags_.applyTo(s, mouse); !given) return trouble(given.error());
    sampling_.applyTo(s);
    if (mouse)
        if (Status inRange = checkMouseSetting(mouse->x, mouse->y); !inRange) return trouble(inRange.error());
    // The commands' watchdog limits unless given (a library Session has none).
    if (!s.frameTimeout) s.frameTimeout = defaults::kFrameTimeoutSeconds;
    if (!s.compileTimeout) s.compileTimeout = defaults::kCompileTimeoutSeconds;
    if (frames_) {
        if (Status frames = checkFramesSetting(*frames_); !frames) return trouble(frames.error());
        settings.frames = *frames_;
    }
    if (pass_.size() == 1 && pass_[0] >= 'A' && pass_[0] <= 'D') pass_ = std::string("Buffer ") + pass_;
    if (pass_ != "Image" && pass_.rfind("Buffer ", 0) != 0)
        return usage("--pass " + pass_ + ": expected Image or \"Buffer A\" .. \"Buffer D\"");
    settings.pass = pass_;
    if (tolerancePsnr_ && maxDiff_) return usage("--tolerance-psnr and --max-diff cannot be combined");
    if (tolerancePsnr_) {
        if (*tolerancePsnr_ <= 0) return usage("--tolerance-psnr must be more than 0 dB");
        settings.tolerance.minPsnr = *tolerancePsnr_;
    }
    if (maxDiff_) {
        if (*maxDiff_ < 0 || *maxDiff_ > 255) return usage("--max-diff must be between 0 and 255 levels");
        settings.tolerance.maxDiff = *maxDiff_;
    }
    if (mouse)
        settings.input = [x = mouse->x, y = mouse->y](int frame, double) {
            return frame == 0 ? std::vector<InputEvent>{InputEvent::mouseDown(x, y)} : std::vector<InputEvent>{};
        };
    Result<Shadertoy> a = Shadertoy::load(a_);
    if (!a) return trouble(a.error());
    Result<Shadertoy> b = Shadertoy::load(b_);
    if (!b) return trouble(b.error());
    for (const Diagnostic& notice : a->notices()) printDiagnostic(notice);
    for (const Diagnostic& notice : b->notices()) printDiagnostic(notice);

    CompareFiles files(diffOut_, framesOut_);
    if (Status ready = files.prepare(); !ready) return trouble(ready.error());
    settings.diffImages = files.wantsDiff();
    int stoppedBy = 0;
    bool writeFailed = false;
    // SIGINT / SIGTERM stop the comparison after the frame being compared (its files are written).
    settings.onFrame = [&](const ComparedFrame& f) {
        if (files.any() && !files.add(f, f.width, f.height)) {
            writeFailed = true;
            return false;
        }
        stoppedBy = stopSignal();
        return stoppedBy == 0;
    };
    // A draw or compile past --frame-timeout / --compile-timeout cannot be interrupted: the process
    // ends then (exit 124), as toyhost run's does, instead of waiting for GL to return.
    setWatchdogExpiryHandler([](const Diagnostic& d) { endAfterWatchdog(d, kExitWatchdog); });
    std::optional<Result<CompareReport>> report;
    runOnGlThread([&] { report.emplace(compareShadertoys(*a, *b, settings)); });
    setWatchdogExpiryHandler({});
    // Every file queued is complete (or its error known) before anything is reported.
    const Status written = files.finish();
    if (!*report) return trouble(report->error());
    if (stoppedBy) {
        std::cerr << "toyhost: " << stopSignalName(stoppedBy) << ": stopped after " << (*report)->frames.size()
                  << " compared frames; the files written are complete\n";
        return 128 + stoppedBy;
    }
    if (!written || writeFailed) return trouble(written ? Error("writing the images failed", Code::IoWrite) : written.error());
    const CompareReport& r = **report;
    const std::string verdict = summary(r, settings.tolerance);
    if (json_) {
        std::cout << toJson(r, a_, b_, settings.tolerance, files).dump(2) << "\n";
    } else {
        printTable(r);
        std::printf("%s\n", verdict.c_str());
    }
    flushStdout();  // before the lines on stderr; a failure is said when the command ends
    if (json_) std::cerr << "toyhost: " << verdict << "\n";
    auto listFiles = [](const std::vector<std::string>& list, const char* what) {
        if (list.empty()) return;
        std::cerr << "toyhost: wrote " << list.size() << " " << what << ": " << list.front();
        if (list.size() > 1) std::cerr << " .. " << list.back();
        std::cerr << "\n";
    };
    listFiles(files.diffs(), files.diffs().size() == 1 ? "difference image" : "difference images");
    listFiles(files.frames(), "frame images");
    return r.equal() ? kExitOk : kExitDiffer;
}

}  // namespace toyhost::cli
