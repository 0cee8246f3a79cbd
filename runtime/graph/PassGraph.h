// The pass graph: from a validated manifest, decides (without any GL) the order passes run in,
// which buffer each pass writes, and which texture every channel sees: this frame's output of a
// buffer that ran earlier, or the previous frame's output of itself or of a later buffer.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// Which output of a buffer a channel samples.
enum class FrameAge { Current, Previous };

struct ChannelPlan {
    ChannelKind kind = ChannelKind::None;
    int buffer = -1;                    // ChannelKind::Buffer only
    FrameAge age = FrameAge::Current;   // ChannelKind::Buffer and CubeBuffer
    // The filter and wrap the channel samples with. As on the site, which sets them on the texture
    // object before each draw, two channels of one pass that read the same buffer texture both
    // get the settings of the higher channel.
    SamplerDesc sampler;
};

struct PassPlan {
    PassId id = PassId::Image;
    int targetBuffer = -1;              // Buffer A..D: 0..3; -1 for Cube A and Image
    bool targetCube = false;            // Cube A: renders the six faces of the cube buffer
    std::array<ChannelPlan, kChannelCount> channels;
};

// Each buffer owns two textures (slots 0 and 1). `step` counts the frames rendered since the
// buffers were created, across restarts and rewinds of time (the Player owns it; it is not
// iFrame, which a restart resets): on step s a buffer renders into slot s % 2, which then is its
// "last rendered" texture; the other slot holds step s-1's output.
inline int slotWritten(std::uint64_t step) { return static_cast<int>(step & 1); }
inline int slotRead(FrameAge age, std::uint64_t step) {
    return age == FrameAge::Current ? slotWritten(step) : slotWritten(step + 1);
}

struct PassGraph {
    std::vector<PassPlan> passes;                  // in execution order, Image last
    std::array<bool, kBufferCount> bufferUsed{};   // a pass exists for this buffer
    std::array<bool, kBufferCount> bufferMipmapped{};  // some channel samples it with `mipmap`
    bool cubeUsed = false;                         // the shadertoy has Cube A
    bool cubeMipmapped = false;

    // True when `other` binds and samples exactly the same (passes, channels, sampler settings,
    // buffers and their mipmaps); the code of the passes may differ.
    bool sameStructure(const PassGraph& other) const;
};

bool operator==(const ChannelPlan& a, const ChannelPlan& b);

PassGraph buildPassGraph(const ManifestDesc& manifest);

}  // namespace toyhost
