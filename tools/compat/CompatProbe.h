// One compatibility probe: load an export, render a few frames headless and judge the output
// (nearly one colour, NaN/Inf in buffers, whether a pass rests on stand-ins). Needs GL: creates
// its own EGL context; run it in a child process so a hang can be killed.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "FrameMeasure.h"
#include "gl/HeadlessContext.h"

namespace toyhost::compat {

// The size a frame that stays one colour is rendered at a second time, at least.
inline constexpr int kSecondWidth = 320;
inline constexpr int kSecondHeight = 180;
// The site's own canvas, the third size: shaders that draw at fixed pixel positions of an 800x450
// layout show nothing at smaller sizes.
inline constexpr int kSiteWidth = 800;
inline constexpr int kSiteHeight = 450;

struct ProbeSettings {
    int width = 160;
    int height = 90;
    int frames = 10;
    // A frame that is still one colour after `frames` frames may be a fade-in or a shader waiting
    // for input: keep rendering until iTime reaches this (a bound in frames, not wall time).
    double patienceSeconds = 5.0;
    // A frame is degenerate when fewer than this share of its pixels differ from its dominant
    // colour (FrameMeasure.h).
    double minOtherShare = kMinOtherShare;
    std::vector<std::filesystem::path> mediaFolders;
    toyhost::EglPlatform eglPlatform = toyhost::EglPlatform::Automatic;
    // Where the last judged Image frame goes as <id>.png (empty: nowhere), to look at.
    std::filesystem::path framesOut;
    // Check a passing verdict that used stand-ins again with them unbound (black), to say whether
    // the verdict depends on them.
    bool checkStandIns = true;
};

struct ProbeResult {
    std::string file;                      // file name of the export
    std::string id, name;
    int passes = 0;
    bool loaded = false;                   // the export parsed
    bool compiled = false;                 // every pass compiled and linked
    int framesRendered = 0;
    double msPerFrame = 0;                 // CPU time per frame of the first `frames` frames
    double firstNonUniformTime = -1;       // iTime when a uniform Image first changed, if it did later
    // The Image is (nearly) one colour: fewer than minOtherShare of its pixels differ from its
    // dominant colour by more than kColourTolerance.
    bool uniformImage = false;
    // That dominant colour changed between the frames judged: a full-screen flash or fade, which
    // is valid output, not a degenerate one.
    bool uniformColourChanged = false;
    FrameShare share;                      // the last judged Image frame's measure
    double otherShareAtFrames = 0;         // share.otherShare after the first `frames` frames
    int judgedWidth = 0, judgedHeight = 0; // the size it was judged at
    std::string glError;                   // a GL error after rendering ("GL_INVALID_OPERATION")
    std::vector<std::string> nonFiniteBuffers;  // "Buffer A: 12 NaN, 0 Inf"
    std::vector<std::string> standIns;     // stock media names replaced by stand-ins
    std::vector<std::string> standInIds;   // their ids as the export writes them
    // Whether a passing verdict depends on its stand-ins, found by rendering again with them
    // unbound (black): "" (no stand-ins, or not checked), "none" (the same picture without them),
    // "picture" (a different picture that still passes), "verdict" (degenerate without them: the
    // pass rests on the stand-in's content).
    std::string standInEffect;
    std::vector<std::string> notices;
    std::string error;                     // why it did not load, compile or render
    std::string secondSize;                // "320x180" when the first size gave one colour and this one was tried
    std::string siteSize;                  // "800x450" when that was tried too (still one colour)
    std::string keyHeld;                   // the key whose holding made a one-colour shader draw ("Space")
    bool keysTried = false;                // the key script was tried (still one colour)
    // The run without any input (the key script's first frame) draws: the probe's mouse drag made
    // the picture one colour (a mouse-driven viewer pointed at nothing).
    bool drawsWithoutInput = false;
    // The phase the probe's CPU time ran out in, when it did after a verdict was reached ("" when
    // not): the verdict is the one reached before, and this says what could not be finished.
    std::string ranOutIn;
    std::vector<std::uint8_t> lastImage;   // the last judged Image frame (RGBA8, not in the JSON)

    // The picture is judged; NaN/Inf in a buffer is a note (packed data, masked pixels and a
    // normalize(0) outside the drawn area are NaN with a right picture).
    bool degenerate() const { return uniformImage && !uniformColourChanged; }
    bool passed() const { return compiled && framesRendered > 0 && glError.empty() && !degenerate(); }
};

// What a probe does, in order; a probe reports each phase as it starts (ProbeProgress), so that
// a runner that kills it at its CPU limit knows what ran out and keeps what was reached before.
enum class ProbePhase { Compile, FirstFrames, FadeIn, SecondSize, SiteSize, KeyScript, StandInCheck, Done };
const char* phaseName(ProbePhase phase);   // "compile", "first frames", "fade-in search", ...
std::optional<ProbePhase> phaseNamed(const std::string& name);
// Called as each phase starts, with the best result so far (its verdict, once one was reached:
// compiled and framesRendered > 0, stands if the probe goes no further).
using ProbeProgress = std::function<void(const ProbeResult& soFar, ProbePhase starting)>;

ProbeResult runProbe(const std::filesystem::path& exportFile, const ProbeSettings& settings,
                     const ProbeProgress& progress = {});

// The result a runner keeps for a probe killed at its CPU limit of `seconds`, from its last
// report: the verdict reached before (with ranOutIn) or, without one, an error naming the phase.
ProbeResult timedOutResult(ProbeResult last, ProbePhase running, int seconds);

// What the table says about a verdict's stand-ins ("" when it has none or they were not checked).
std::string standInEffectText(const ProbeResult& result);

nlohmann::json toJson(const ProbeResult& result);
ProbeResult fromJson(const nlohmann::json& json);

}  // namespace toyhost::compat
