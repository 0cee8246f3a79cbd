// SoundRenderer: renders a shadertoy's Sound pass (mainSound) as the site does, once and up front:
// blocks of 512x512 samples drawn into an RGBA8 target (two 16-bit values per pixel, see
// capture/SoundEncoding.h), read back and decoded to stereo floats at 44100 Hz. Its channels are
// bound by the same bindChannels() as every other pass (render/ChannelBindings.h). Writing the
// result as an audio file is capture/SoundFile.h's. Needs a GL context (made current here).
#pragma once

#include <functional>
#include <vector>

#include "core/Result.h"
#include "gl/GlContext.h"
#include "manifest/ManifestDesc.h"
#include "media/ChannelMedia.h"
#include "shader/PassSource.h"

namespace toyhost {

struct SoundRenderDesc {
    double seconds = 0;  // 0: the site's 180 s (core/Defaults.h)
    // The Sound pass's texts, prepared off the GL thread (PlayerPlan::soundSource). Required.
    const PassSource* source = nullptr;
    // Asked between blocks; true stops the rendering with a Code::Interrupted error.
    std::function<bool()> stopRequested;
};

// Interleaved stereo samples (left, right, ...) of `manifest`'s Sound pass, seconds * 44100 pairs,
// its channels from `media` (made by planPlayer). For a watchdog attached to `context`
// (GlContext::gpuActivity()), each block's draw and readback is published as Drawing pass
// "Sound" with the block's number as the frame, so that a runaway mainSound can be ended. The Sound pass may read images, cubemaps and
// volumes; any other channel is an error naming it.
Result<std::vector<float>> renderSound(GlContext& context, const ManifestDesc& manifest, const ChannelMedia& media,
                                       const SoundRenderDesc& desc = {});

}  // namespace toyhost
