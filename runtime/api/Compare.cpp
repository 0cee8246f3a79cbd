// toyhost::compareShadertoys (include/toyhost/Compare.h): two headless Sessions stepped together
// with the same settings and the same input events, one pass read back from each after every frame
// and compared by compareImages (runtime/compare). Needs no GL context of the caller's: each
// session has its own headless one.
#include <toyhost/Compare.h>
#include <toyhost/Session.h>

#include <algorithm>
#include <ctime>
#include <limits>

#include "api/ShadertoyAccess.h"
#include "compare/CompareChecks.h"
#include "core/Defaults.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

namespace {

// "now" once, so that both sessions see the same iDate.
std::string localNow() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S", &local);
    return text;
}

// The run settings both get: the caller's, else A's manifest defaults, else B's, else toyhost's.
// What the caller gave is left as given, for the sessions to check.
SessionSettings commonSettings(const Shadertoy& a, const Shadertoy& b, const SessionSettings& given) {
    SessionSettings s = given;
    const RunDefaults& da = ShadertoyAccess::desc(a).runDefaults;
    const RunDefaults& db = ShadertoyAccess::desc(b).runDefaults;
    if (!s.width && !s.height) {
        s.width = da.width.value_or(db.width.value_or(defaults::kCanvasWidth));
        s.height = da.height.value_or(db.height.value_or(defaults::kCanvasHeight));
    }
    if (!s.fps) s.fps = da.fps.value_or(db.fps.value_or(defaults::kFps));
    if (!s.date) s.date = localNow();
    return s;
}

bool hasPass(const Shadertoy& shadertoy, const std::string& pass) {
    const std::vector<std::string> passes = shadertoy.passes();
    return std::find(passes.begin(), passes.end(), pass) != passes.end();
}

}  // namespace

Result<CompareReport> compareShadertoys(const Shadertoy& a, const Shadertoy& b, const CompareSettings& settings) {
    const std::string& pass = settings.pass;
    if (pass != "Image" && pass != "Buffer A" && pass != "Buffer B" && pass != "Buffer C" && pass != "Buffer D")
        return Error("compare: pass \"" + pass + "\": expected Image or \"Buffer A\" .. \"Buffer D\"", Code::Usage);
    if (!hasPass(a, pass)) return fileError(a.path().string(), "compare: it has no pass " + pass, Code::Usage);
    if (!hasPass(b, pass)) return fileError(b.path().string(), "compare: it has no pass " + pass, Code::Usage);
    if (settings.frames < 0) return Error("compare: frames must not be negative", Code::Usage);
    if (Status checked = checkCompareTolerance(settings.tolerance, settings.diffGain); !checked) return checked.error();
    const RunDefaults& da = ShadertoyAccess::desc(a).runDefaults;
    const RunDefaults& db = ShadertoyAccess::desc(b).runDefaults;
    const int frames = settings.frames > 0 ? settings.frames
                                           : da.frames.value_or(db.frames.value_or(defaults::kCompareFrames));

    // Both sessions step through the same fixed-step input: the scripts replayed by each, the
    // caller's extra events given to both.
    const SessionSettings common = commonSettings(a, b, settings.session);
    Result<std::unique_ptr<Session>> sessionA = Session::createHeadless(a, common);
    if (!sessionA) return sessionA.error();
    Result<std::unique_ptr<Session>> sessionB = Session::createHeadless(b, common);
    if (!sessionB) return sessionB.error();
    Session& first = **sessionA;
    Session& second = **sessionB;

    CompareReport report;
    report.width = first.width();
    report.height = first.height();
    report.pass = pass;
    report.fps = *common.fps;
    report.startTime = common.startTime;
    report.minPsnr = std::numeric_limits<double>::infinity();
    const std::size_t values = static_cast<std::size_t>(report.width) * report.height * 4;
    std::vector<std::uint8_t> pixelsA(values), pixelsB(values), diff;
    std::vector<InputEvent> events;
    const bool wantDiff = settings.keepDiffImages || settings.diffImages;
    const int channels = pass == "Image" ? 3 : 4;  // Image's alpha is always 1
    for (int n = 0; n < frames; ++n) {
        const double time = first.timeOf(n);
        events.clear();
        if (settings.input)
            for (const InputEvent& e : settings.input(n, time)) events.push_back(e);
        if (Status s = first.step(events); !s) return inFile(a.path().string(), s.error());
        if (Status s = second.step(events); !s) return inFile(b.path().string(), s.error());
        if (Status s = first.read(pass, pixelsA); !s) return s.error();
        if (Status s = second.read(pass, pixelsB); !s) return s.error();
        Result<FrameDifference> d = compareImages(pixelsA, pixelsB, report.width, report.height, channels,
                                                  settings.tolerance, wantDiff ? &diff : nullptr, settings.diffGain);
        if (!d) return d.error();
        d->frame = n;
        d->time = time;
        if (!d->withinTolerance && !report.firstDifferingFrame) report.firstDifferingFrame = n;
        report.minPsnr = std::min(report.minPsnr, d->psnr);
        report.maxDiff = std::max(report.maxDiff, d->maxDiff);
        const bool showDiff = wantDiff && !d->withinTolerance;
        if (showDiff && settings.keepDiffImages) d->diffImage = diff;
        report.frames.push_back(std::move(*d));
        if (settings.onFrame) {
            const ComparedFrame compared{report.frames.back(), report.width, report.height, pixelsA, pixelsB,
                                         showDiff ? std::span<const std::uint8_t>(diff) : std::span<const std::uint8_t>()};
            if (!settings.onFrame(compared)) break;
        }
    }
    return report;
}

}  // namespace toyhost
