#include "CompatProbe.h"

#include "ProbeScript.h"

#include <GLES3/gl3.h>

#include <ctime>
#include <algorithm>
#include <cmath>
#include <optional>
#include <array>

#include "export/LoadShadertoy.h"
#include "gl/GlContext.h"
#include "gl/HeadlessContext.h"
#include "image/ImageWriters.h"
#include "session/SessionCore.h"
#include "timing/FrameClock.h"
#include "timing/Timeline.h"

namespace toyhost::compat {
namespace fs = std::filesystem;

namespace {

// The session's notices (stand-ins, preprocessing, warnings) as the table's lines.
class NoticeCollector final : public SessionObserver {
public:
    explicit NoticeCollector(std::vector<std::string>& lines) : lines_(lines) {}
    void notice(const Diagnostic& notice) override { lines_.push_back(formatDiagnostic(notice)); }

private:
    std::vector<std::string>& lines_;
};


// `firstUniform` keeps the dominant colour of the first nearly uniform frame judged, to tell a
// flash from a frozen screen.
void judgeOutput(const SessionCore& session, const ProbeSettings& settings, ProbeResult& result,
                 std::optional<std::array<std::uint8_t, 3>>& firstUniform) {
    const ManifestDesc& manifest = session.manifest();
    session.readRgba8(PassId::Image, result.lastImage);
    result.share = measureFrame(result.lastImage);
    result.uniformImage = nearlyUniform(result.share, settings.minOtherShare);
    if (result.uniformImage && !result.lastImage.empty()) {
        if (!firstUniform) firstUniform = result.share.dominant;
        else if (colourChanged(*firstUniform, result.share.dominant)) result.uniformColourChanged = true;
    }
    std::vector<float> floats;
    for (const PassDesc& pass : manifest.passes) {
        if (!isBuffer(pass.id)) continue;
        session.readRgba32f(pass.id, floats);
        size_t nan = 0, inf = 0;
        for (float v : floats) {
            nan += std::isnan(v);
            inf += std::isinf(v);
        }
        if (nan || inf)
            result.nonFiniteBuffers.push_back(std::string(passName(pass.id)) + ": " + std::to_string(nan) + " NaN, " +
                                              std::to_string(inf) + " Inf");
    }
}

// The channels showing a stand-in (by the id the export writes) left unbound: they read black,
// declared with the sampler type they had, so the shader still compiles.
void unbindStandIns(ManifestDesc& manifest, const std::vector<std::string>& ids) {
    auto unbind = [&](PassDesc& pass) {
        for (ChannelDesc& channel : pass.channels) {
            if (channel.kind == ChannelKind::None || channel.kind == ChannelKind::Buffer ||
                channel.kind == ChannelKind::CubeBuffer || channel.kind == ChannelKind::Keyboard)
                continue;
            const std::string id = channel.media.empty() ? channel.file.string() : channel.media;
            if (std::find(ids.begin(), ids.end(), id) == ids.end()) continue;
            const SamplerType declared = channel.samplerType;
            channel = ChannelDesc{};
            channel.samplerType = declared;
        }
    };
    for (PassDesc& pass : manifest.passes) unbind(pass);
    if (manifest.sound) unbind(*manifest.sound);
}

// How a run gives input: the visitor's mouse drag (with patience for fade-ins), or the key script
// (ProbeScript.h), judged on every frame until the picture draws.
enum class ProbeInput { Mouse, Keys };

// `blankIds`: stand-ins (by id) to leave unbound; `wallClock`: iDate at frame 0, the same for
// every run of one probe so that runs compare; `report`: the phases as they start.
ProbeResult probeAtOneSize(const fs::path& exportFile, const ProbeSettings& settings,
                           const std::vector<std::string>& blankIds, double wallClock, const ProbeProgress& report,
                           ProbeInput input = ProbeInput::Mouse) {
    ProbeResult result;
    result.file = exportFile.filename().string();
    // An export is known by its file name (<id>.json); a manifest folder by the folder's name.
    std::error_code ec;
    result.id = fs::is_directory(exportFile, ec) ? exportFile.filename().string() : exportFile.stem().string();
    Result<ManifestDesc> manifest = loadShadertoy(exportFile);
    if (!manifest) {
        result.error = firstErrorLine(manifest.error().text());
        return result;
    }
    result.loaded = true;
    result.name = manifest->name;
    result.passes = static_cast<int>(manifest->passes.size()) + (manifest->commonSource ? 1 : 0);

    // The probe is a session like any run (the same preparation, compile checks and GL thread),
    // driven frame by frame with the visitor's mouse below.
    SessionOptions options;
    options.target = exportFile;
    if (!blankIds.empty()) {
        auto changed = std::make_shared<ManifestDesc>(*manifest);
        unbindStandIns(*changed, blankIds);
        options.shadertoy = std::move(changed);
    }
    options.settings.width = settings.width;
    options.settings.height = settings.height;
    options.frames = 1;
    options.settings.mediaFolders = settings.mediaFolders;
    options.eglPlatform = settings.eglPlatform;
    options.settings.date = wallClockText(wallClock);
    Result<SessionPlan> plan = prepareSession(options);
    if (!plan) {
        result.error = firstErrorLine(plan.error().text());
        return result;
    }
    for (const StandInUse& standIn : plan->shadertoy.images.standIns()) {
        if (std::find(result.standIns.begin(), result.standIns.end(), standIn.name) == result.standIns.end())
            result.standIns.push_back(standIn.name);
        if (std::find(result.standInIds.begin(), result.standInIds.end(), standIn.id) == result.standInIds.end())
            result.standInIds.push_back(standIn.id);
    }
    HeadlessOptions headless;
    headless.platform = settings.eglPlatform;
    auto context = createHeadlessContext(headless);
    if (!context) {
        result.error = context.error().text();
        return result;
    }
    NoticeCollector notices(result.notices);
    // Time and date come from the fixed-step input every headless run uses.
    Timeline timeline(timelineOf(*plan));
    report(result, ProbePhase::Compile);
    auto session = SessionCore::start(std::move(*plan), *context, notices);
    if (!session) {
        result.error = firstErrorLine(session.error().text());
        return result;
    }
    result.compiled = true;
    report(result, ProbePhase::FirstFrames);
    SessionCore* core = session->get();

    // Like a visitor, the probe drags the mouse across the canvas from frame 1 and lets go before
    // the last frames (ProbeScript.h), so shaders that show nothing until clicked get their click.
    std::vector<InputEvent> events;
    auto frameAt = [&](int frame) {
        // The key script starts on frame 1: frame 0 has no input at all (no mouse either).
        events = input == ProbeInput::Keys ? probeKeysAt(frame - 1)
                                           : probeMouseAt(frame, settings.frames, settings.width, settings.height);
        const FrameTime time = timeline.next(frame, events);
        (void)(*session)->renderFrame(time, events);
        // Finish each frame so ms/frame is the real shading cost: llvmpipe drops queued work for
        // tiles that a later draw overwrites before anything reads them.
        core->finish();
        result.framesRendered = frame + 1;
    };
    // CPU time of the process (llvmpipe's threads included), not wall time, which grows with the
    // machine's load.
    std::optional<std::array<std::uint8_t, 3>> firstUniform;
    auto checkGl = [&] {
        if (GLenum error = glGetError(); error != GL_NO_ERROR && result.glError.empty()) {
            result.glError = glErrorName(error);
            result.error = "GL error " + result.glError + " while rendering";
        }
    };
    result.judgedWidth = settings.width;
    result.judgedHeight = settings.height;
    if (input == ProbeInput::Keys) {
        // Each key in turn, judged on every frame: the first frame that draws names its key.
        const std::clock_t start = std::clock();
        for (int frame = 0; frame <= probeKeyFrames(); ++frame) {
            frameAt(frame);
            result.nonFiniteBuffers.clear();
            judgeOutput(*core, settings, result, firstUniform);
            if (!result.uniformImage || result.uniformColourChanged) {
                if (frame == 0) {
                    result.keyHeld = "";  // it draws with no input: the probe's mouse drag hid it
                    result.drawsWithoutInput = true;
                } else {
                    const int held = probeKeyHeldAt(frame - 1);
                    result.keyHeld = kProbeKeys[held >= 0 ? held : kProbeKeyCount - 1].name;
                }
                break;
            }
        }
        result.msPerFrame = 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC /
                            std::max(1, result.framesRendered);
        checkGl();
        return result;
    }
    const std::clock_t start = std::clock();
    for (int frame = 0; frame < settings.frames; ++frame) frameAt(frame);
    const double seconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    result.msPerFrame = 1000.0 * seconds / settings.frames;
    checkGl();
    judgeOutput(*core, settings, result, firstUniform);
    result.otherShareAtFrames = result.share.otherShare;
    if (result.uniformImage && !result.uniformColourChanged && settings.patienceSeconds > 0)
        report(result, ProbePhase::FadeIn);
    // Patience for fade-ins and shaders that need time: check every quarter second of iTime, up to
    // a bound in iTime (frames), never in wall time, so the verdict does not depend on load.
    const int quarterSecond = std::max(1, static_cast<int>(std::lround(timeline.fps() / 4)));
    for (int frame = settings.frames;
         result.uniformImage && !result.uniformColourChanged && timeline.at(frame).time < settings.patienceSeconds;
         ++frame) {
        frameAt(frame);
        if (frame % quarterSecond != 0) continue;
        result.nonFiniteBuffers.clear();
        judgeOutput(*core, settings, result, firstUniform);
        if (!result.uniformImage || result.uniformColourChanged) result.firstNonUniformTime = timeline.at(frame).time;
    }
    checkGl();
    return result;
}

// One colour at the small size: shaders drawing at fixed pixel positions (a layout for 800x450, a
// 100 px ring) can miss a 160x90 canvas, and some draw only while a key is held. Before calling
// the frame empty, render it at 320x180, at the site's 800x450, and at the first size with each
// likely key held in turn; the result says what was tried. While a later attempt runs, the
// verdict reported is the first one (what stands if the CPU time runs out).
ProbeResult probeUntilItDraws(const fs::path& exportFile, const ProbeSettings& settings,
                              const std::vector<std::string>& blankIds, double wallClock, const ProbeProgress& report) {
    ProbeResult first = probeAtOneSize(exportFile, settings, blankIds, wallClock, report);
    if (!first.degenerate() || !first.compiled || !first.glError.empty()) return first;
    auto attempt = [&](const ProbeSettings& at, ProbePhase phase, ProbeInput input) {
        report(first, phase);
        return probeAtOneSize(exportFile, at, blankIds, wallClock,
                              [&](const ProbeResult&, ProbePhase) { report(first, phase); }, input);
    };
    ProbeSettings larger = settings;
    larger.width = std::max(settings.width * 2, kSecondWidth);
    larger.height = std::max(settings.height * 2, kSecondHeight);
    ProbeResult second = attempt(larger, ProbePhase::SecondSize, ProbeInput::Mouse);
    first.secondSize = std::to_string(larger.width) + "x" + std::to_string(larger.height);
    if (second.passed()) {
        second.secondSize = first.secondSize;
        second.msPerFrame = first.msPerFrame;  // the table's timings stay at one size
        return second;
    }
    if (larger.width < kSiteWidth && larger.height < kSiteHeight) {
        ProbeSettings site = settings;
        site.width = kSiteWidth;
        site.height = kSiteHeight;
        site.patienceSeconds = 0;  // the frames only: a large canvas is slow on the CPU
        ProbeResult third = attempt(site, ProbePhase::SiteSize, ProbeInput::Mouse);
        first.siteSize = std::to_string(kSiteWidth) + "x" + std::to_string(kSiteHeight);
        if (third.passed()) {
            third.secondSize = first.secondSize;
            third.siteSize = first.siteSize;
            third.msPerFrame = first.msPerFrame;
            return third;
        }
    }
    ProbeResult keys = attempt(settings, ProbePhase::KeyScript, ProbeInput::Keys);
    first.keysTried = true;
    if (keys.passed()) {
        keys.secondSize = first.secondSize;
        keys.siteSize = first.siteSize;
        keys.keysTried = !keys.drawsWithoutInput;
        keys.msPerFrame = first.msPerFrame;
        return keys;
    }
    return first;
}

}  // namespace

const char* phaseName(ProbePhase phase) {
    switch (phase) {
        case ProbePhase::Compile: return "compile";
        case ProbePhase::FirstFrames: return "first frames";
        case ProbePhase::FadeIn: return "fade-in search";
        case ProbePhase::SecondSize: return "second size";
        case ProbePhase::SiteSize: return "site size";
        case ProbePhase::KeyScript: return "key script";
        case ProbePhase::StandInCheck: return "stand-in check";
        case ProbePhase::Done: return "done";
    }
    return "done";
}

std::optional<ProbePhase> phaseNamed(const std::string& name) {
    for (ProbePhase phase : {ProbePhase::Compile, ProbePhase::FirstFrames, ProbePhase::FadeIn, ProbePhase::SecondSize,
                             ProbePhase::SiteSize, ProbePhase::KeyScript, ProbePhase::StandInCheck, ProbePhase::Done})
        if (name == phaseName(phase)) return phase;
    return std::nullopt;
}

ProbeResult timedOutResult(ProbeResult last, ProbePhase running, int seconds) {
    if (last.compiled && last.framesRendered > 0 && running != ProbePhase::Compile &&
        running != ProbePhase::FirstFrames) {
        last.ranOutIn = phaseName(running);  // the verdict reached stands
        return last;
    }
    last.error = "timed out after " + std::to_string(seconds) + " s of CPU time in the " + phaseName(running) +
                 " phase" + (running == ProbePhase::Compile ? " (the shader compiler was still running)" : "");
    return last;
}

ProbeResult runProbe(const fs::path& exportFile, const ProbeSettings& settings, const ProbeProgress& progress) {
    const ProbeProgress report = progress ? progress : [](const ProbeResult&, ProbePhase) {};
    const double wallClock = localWallClockNow();
    ProbeResult result = probeUntilItDraws(exportFile, settings, {}, wallClock, report);
    if (settings.checkStandIns && result.passed() && !result.standInIds.empty()) {
        report(result, ProbePhase::StandInCheck);
        // The same probe with the stand-ins unbound, at the size that passed: a picture that does
        // not change never read them; one that goes degenerate passed on their content alone.
        ProbeSettings same = settings;
        same.width = result.judgedWidth;
        same.height = result.judgedHeight;
        const ProbeResult blank = probeAtOneSize(exportFile, same, result.standInIds, wallClock,
                                                 [&](const ProbeResult&, ProbePhase) { report(result, ProbePhase::StandInCheck); });
        if (!blank.passed()) result.standInEffect = "verdict";
        else if (blank.framesRendered == result.framesRendered && blank.lastImage == result.lastImage)
            result.standInEffect = "none";
        else result.standInEffect = "picture";
    }
    if (!settings.framesOut.empty() && !result.lastImage.empty()) {
        std::error_code ec;
        fs::create_directories(settings.framesOut, ec);
        (void)writePng(settings.framesOut / (result.id + ".png"), result.judgedWidth, result.judgedHeight,
                       result.lastImage);
    }
    return result;
}

std::string standInEffectText(const ProbeResult& r) {
    if (r.standInEffect == "none") return "the same picture without them";
    if (r.standInEffect == "picture") return "the picture depends on them";
    if (r.standInEffect == "verdict") return "passes only with them: one colour without them";
    return "";
}

nlohmann::json toJson(const ProbeResult& r) {
    return {{"file", r.file},
            {"id", r.id},
            {"name", r.name},
            {"passes", r.passes},
            {"loaded", r.loaded},
            {"compiled", r.compiled},
            {"frames_rendered", r.framesRendered},
            {"ms_per_frame", std::round(r.msPerFrame * 100) / 100},
            {"uniform_image", r.uniformImage},
            {"uniform_colour_changed", r.uniformColourChanged},
            {"other_share", std::round(r.share.otherShare * 1e6) / 1e6},
            {"other_share_at_frames", std::round(r.otherShareAtFrames * 1e6) / 1e6},
            {"mean_level", std::round(r.share.meanLevel * 1000) / 1000},
            {"dominant", {r.share.dominant[0], r.share.dominant[1], r.share.dominant[2]}},
            {"judged_size", std::to_string(r.judgedWidth) + "x" + std::to_string(r.judgedHeight)},
            {"gl_error", r.glError},
            {"first_non_uniform_time", r.firstNonUniformTime},
            {"non_finite_buffers", r.nonFiniteBuffers},
            {"stand_ins", r.standIns},
            {"stand_in_ids", r.standInIds},
            {"stand_in_effect", r.standInEffect},
            {"notices", r.notices},
            {"error", r.error},
            {"second_size", r.secondSize},
            {"site_size", r.siteSize},
            {"key_held", r.keyHeld},
            {"keys_tried", r.keysTried},
            {"draws_without_input", r.drawsWithoutInput},
            {"ran_out_in", r.ranOutIn},
            {"passed", r.passed()}};
}

ProbeResult fromJson(const nlohmann::json& j) {
    ProbeResult r;
    r.file = j.value("file", "");
    r.id = j.value("id", "");
    r.name = j.value("name", "");
    r.passes = j.value("passes", 0);
    r.loaded = j.value("loaded", false);
    r.compiled = j.value("compiled", false);
    r.framesRendered = j.value("frames_rendered", 0);
    r.msPerFrame = j.value("ms_per_frame", 0.0);
    r.uniformImage = j.value("uniform_image", false);
    r.uniformColourChanged = j.value("uniform_colour_changed", false);
    r.glError = j.value("gl_error", "");
    r.firstNonUniformTime = j.value("first_non_uniform_time", -1.0);
    r.nonFiniteBuffers = j.value("non_finite_buffers", std::vector<std::string>{});
    r.standIns = j.value("stand_ins", std::vector<std::string>{});
    r.standInIds = j.value("stand_in_ids", std::vector<std::string>{});
    r.standInEffect = j.value("stand_in_effect", "");
    r.share.otherShare = j.value("other_share", 0.0);
    r.share.meanLevel = j.value("mean_level", 0.0);
    r.otherShareAtFrames = j.value("other_share_at_frames", 0.0);
    r.share.dominantShare = 1.0 - r.share.otherShare;
    if (auto d = j.find("dominant"); d != j.end() && d->is_array() && d->size() == 3)
        for (int k = 0; k < 3; ++k) r.share.dominant[k] = (*d)[k].get<std::uint8_t>();
    if (std::sscanf(j.value("judged_size", "").c_str(), "%dx%d", &r.judgedWidth, &r.judgedHeight) != 2)
        r.judgedWidth = r.judgedHeight = 0;
    r.notices = j.value("notices", std::vector<std::string>{});
    r.error = j.value("error", "");
    r.secondSize = j.value("second_size", "");
    r.siteSize = j.value("site_size", "");
    r.keyHeld = j.value("key_held", "");
    r.keysTried = j.value("keys_tried", false);
    r.drawsWithoutInput = j.value("draws_without_input", false);
    r.ranOutIn = j.value("ran_out_in", "");
    return r;
}

}  // namespace toyhost::compat
