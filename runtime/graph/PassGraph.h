// The pass graph: from a validated manifest, decides (without any GL) the order passes run in,
// which buffer each pass writes, and which texture every channel sees: this frame's output of a
// buffer that ran earlier, or the previous frame's output of itself or of a later buffer.
#pragma once

#include <array>
#include <vector>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// Which output of a buffer a channel samples.
enum class FrameAge { Current, Previous };

struct ChannelPlan {
    ChannelKind kind = ChannelKind::None;
    int buffer = -1;                    // ChannelKind::Buffer only
    FrameAge age = FrameAge::Current;   // ChannelKind::Buffer only
    SamplerDesc sampler;
};

struct PassPlan {
    PassId id = PassId::Image;
    int targetBuffer = -1;              // -1: the Image pass (renders to the canvas)
    std::array<ChannelPlan, kChannelCount> channels;
};

// Each buffer owns two textures (slots 0 and 1). On frame n a buffer renders into slot n % 2,
// which then is its "last rendered" texture; the other slot holds frame n-1's output.
inline int slotWritten(int frame) { return frame & 1; }
inline int slotRead(FrameAge age, int frame) {
    return age == FrameAge::Current ? slotWritten(frame) : slotWritten(frame + 1);
}

struct PassGraph {
    std::vector<PassPlan> passes;                  // in execution order, Image last
    std::array<bool, kBufferCount> bufferUsed{};   // a pass exists for this buffer
    std::array<bool, kBufferCount> bufferMipmapped{};  // some channel samples it with `mipmap`
};

PassGraph buildPassGraph(const ManifestDesc& manifest);

}  // namespace toyhost
