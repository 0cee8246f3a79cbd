// PlayerDesc and PlayerPlan: what a Player is made from. A PlayerDesc is plain settings whose
// zero/absent fields mean "the default" (filled by withDefaults from core/Defaults.h, the one
// place defaults live). A PlayerPlan is everything about a shadertoy that can be prepared without
// GL: the validated manifest, its pass graph, the decoded pixels of every image channel and the
// opened sources of its videos, cameras, music and microphones (media/ChannelMedia.h), so that the
// renderer only makes and updates textures. Plans are made off the GL thread (a file watcher does
// it before a hot reload). No GL needed.
#pragma once

#include <vector>

#include "core/Result.h"
#include "graph/PassGraph.h"
#include "manifest/ManifestDesc.h"
#include "media/ChannelMedia.h"
#include "render/RenderTargets.h"
#include "shader/PassSource.h"
#include "timing/SamplePattern.h"

namespace toyhost {

struct PlayerDesc {
    int width = 0;               // canvas size; 0: defaults::kCanvasWidth x kCanvasHeight
    int height = 0;
    // Render the Image pass into RGBA32F instead of RGBA8 (EXR capture of Image, float checks).
    bool floatImage = false;
    // Where and when Image is drawn in each frame (supersampling, motion blur); the default is the
    // site's single draw at the pixel centres and the frame's time.
    SamplingDesc sampling;
    // A tiled still: the canvas (iResolution) is this size while the targets are width x height,
    // one tile, placed with Player::drawImageAt; 0: the canvas is the targets.
    int canvasWidth = 0;
    int canvasHeight = 0;
    // Tests make allocations fail here to check that resize is all-or-nothing; empty: real GL.
    TextureAllocator allocate;
};

// `desc` with every zero field replaced by its default.
PlayerDesc withDefaults(PlayerDesc desc);

// Checks a canvas size against toyhost's own limits (not GL's, which the Player checks).
Status checkCanvasSize(int width, int height);

struct PlayerPlan {
    ManifestDesc manifest;
    PassGraph graph;
    ChannelMedia images;
    std::vector<Diagnostic> notices;  // the manifest's notices and the stand-ins used
    // Each pass's shader texts (manifest.passes' order), and the Sound pass's when there is one,
    // with their browser-style expansions where they may be needed (a child process): the GL
    // thread only compiles.
    std::vector<PassSource> sources;
    std::optional<PassSource> soundSource;
    MacroDefines defines;  // the run's --define macros, in every pass's texts above
};

// Builds the graph, prepares every pass's shader texts (cpp for the browser-style expansion),
// decodes every image channel and opens every video and audio source (ffprobe and ffmpeg, waits
// of seconds for live sources: call it off the GL thread); every problem is reported at once.
// `defines` go into every pass (shader/MacroDefines.h).
Result<PlayerPlan> planPlayer(ManifestDesc manifest, const MediaOptions& media, MacroDefines defines = {});

}  // namespace toyhost
