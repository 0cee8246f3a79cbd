#include "graph/PassGraph.h"

namespace toyhost {

PassGraph buildPassGraph(const ManifestDesc& manifest) {
    PassGraph graph;
    // Execution position of each buffer; a buffer absent from the manifest is never read
    // (validation guarantees it).
    std::array<int, kBufferCount> position{};
    position.fill(-1);
    for (const PassDesc& pass : manifest.passes) {
        if (isBuffer(pass.id)) {
            position[bufferIndex(pass.id)] = static_cast<int>(graph.passes.size());
            graph.bufferUsed[bufferIndex(pass.id)] = true;
        }
        PassPlan plan;
        plan.id = pass.id;
        plan.targetBuffer = isBuffer(pass.id) ? bufferIndex(pass.id) : -1;
        graph.passes.push_back(plan);
    }
    for (size_t i = 0; i < graph.passes.size(); ++i) {
        const PassDesc& pass = manifest.passes[i];
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& channel = pass.channels[c];
            ChannelPlan& plan = graph.passes[i].channels[c];
            plan.kind = channel.kind;
            plan.sampler = channel.sampler;
            if (channel.kind != ChannelKind::Buffer) continue;
            plan.buffer = channel.buffer;
            // A buffer that already ran this frame gives this frame's output; reading itself or
            // a buffer that runs later gives the previous frame's (Shadertoy's "last rendered").
            plan.age = position[channel.buffer] < static_cast<int>(i) ? FrameAge::Current
                                                                       : FrameAge::Previous;
            if (channel.sampler.filter == Filter::Mipmap) graph.bufferMipmapped[channel.buffer] = true;
        }
    }
    return graph;
}

bool operator==(const ChannelPlan& a, const ChannelPlan& b) {
    return a.kind == b.kind && a.buffer == b.buffer && a.age == b.age && a.sampler.filter == b.sampler.filter &&
           a.sampler.wrap == b.sampler.wrap && a.sampler.vflip == b.sampler.vflip;
}

bool PassGraph::sameStructure(const PassGraph& other) const {
    if (passes.size() != other.passes.size() || bufferUsed != other.bufferUsed ||
        bufferMipmapped != other.bufferMipmapped)
        return false;
    for (size_t i = 0; i < passes.size(); ++i)
        if (passes[i].id != other.passes[i].id || passes[i].targetBuffer != other.passes[i].targetBuffer ||
            passes[i].channels != other.passes[i].channels)
            return false;
    return true;
}

}  // namespace toyhost
