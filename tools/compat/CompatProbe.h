// One compatibility probe: load a Shadertoy export, compile it, render a few frames headless
// and judge the output (uniform colour, NaN/Inf in buffers), collecting stand-ins and notices.
// Creates and uses its own EGL context; run it in a child process so a hang can be killed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gl/HeadlessContext.h"

namespace toyhost::compat {

// The size a frame that stays one colour is rendered at a second time, at least.
inline constexpr int kSecondWidth = 320;
inline constexpr int kSecondHeight = 180;

struct ProbeSettings {
    int width = 160;
    int height = 90;
    int frames = 10;
    // A frame that is still one colour after `frames` frames may be a fade-in or a shader waiting
    // for input: keep rendering until iTime reaches this (a bound in frames, not wall time).
    double patienceSeconds = 5.0;
    std::vector<std::filesystem::path> mediaFolders;
    toyhost::EglPlatform eglPlatform = toyhost::EglPlatform::Automatic;
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
    bool uniformImage = false;             // every Image pixel has the same colour
    // The uniform colour changed between the frames judged: a full-screen flash or fade, which is
    // valid output, not a degenerate one.
    bool uniformColourChanged = false;
    std::string glError;                   // a GL error after rendering ("GL_INVALID_OPERATION")
    std::vector<std::string> nonFiniteBuffers;  // "Buffer A: 12 NaN, 0 Inf"
    std::vector<std::string> standIns;     // stock media names replaced by stand-ins
    std::vector<std::string> notices;
    std::string error;                     // why it did not load, compile or render
    std::string secondSize;                // "320x180" when the first size gave one colour and this one was tried

    // The picture is judged; NaN/Inf in a buffer is a note (packed data, masked pixels and a
    // normalize(0) outside the drawn area are NaN with a right picture).
    bool degenerate() const { return uniformImage && !uniformColourChanged; }
    bool passed() const { return compiled && framesRendered > 0 && glError.empty() && !degenerate(); }
};

ProbeResult runProbe(const std::filesystem::path& exportFile, const ProbeSettings& settings);

nlohmann::json toJson(const ProbeResult& result);
ProbeResult fromJson(const nlohmann::json& json);

}  // namespace toyhost::compat
