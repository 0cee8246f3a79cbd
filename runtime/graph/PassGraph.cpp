#include "graph/PassGraph.h"

#include "manifest/BufferWraps.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace toyhost {

PassGraph buildPassGraph(const ManifestDesc& manifest) {
    PassGraph graph;
    // Execution position of each buffer; a buffer absent from the manifest is never read
    // (validation guarantees it).
    std::array<int, kBufferCount> position{};
    position.fill(-1);
    int cubePosition = -1;
    for (const PassDesc& pass : manifest.passes) {
        if (isBuffer(pass.id)) {
            position[bufferIndex(pass.id)] = static_cast<int>(graph.passes.size());
            graph.bufferUsed[bufferIndex(pass.id)] = true;
        }
        if (pass.id == PassId::CubeA) {
            cubePosition = static_cast<int>(graph.passes.size());
            graph.cubeUsed = true;
        }
        PassPlan plan;
        plan.id = pass.id;
        plan.targetBuffer = isBuffer(pass.id) ? bufferIndex(pass.id) : -1;
        plan.targetCube = pass.id == PassId::CubeA;
        graph.passes.push_back(plan);
    }
    for (size_t i = 0; i < graph.passes.size(); ++i) {
        const PassDesc& pass = manifest.passes[i];
        for (int c = 0; c < kChannelCount; ++c) {
            const ChannelDesc& channel = pass.channels[c];
            ChannelPlan& plan = graph.passes[i].channels[c];
            plan.kind = channel.kind;
            plan.sampler = channel.sampler;
            if (channel.kind == ChannelKind::CubeBuffer) {
                // Only Image runs after Cube A: every other reader sees the previous frame's faces.
                plan.age = cubePosition >= 0 && cubePosition < static_cast<int>(i) ? FrameAge::Current
                                                                                     : FrameAge::Previous;
                if (channel.sampler.filter == Filter::Mipmap) graph.cubeMipmapped = true;
                continue;
            }
            if (channel.kind != ChannelKind::Buffer) continue;
            plan.buffer = channel.buffer;
            // A buffer that already ran this frame gives this frame's output; reading itself or
            // a buffer that runs later gives the previous frame's (Shadertoy's "last rendered").
            plan.age = position[channel.buffer] < static_cast<int>(i) ? FrameAge::Current
                                                                       : FrameAge::Previous;
            if (channel.sampler.filter == Filter::Mipmap) graph.bufferMipmapped[channel.buffer] = true;
        }
    }
    // The site's sampler quirks (effect.js, WebGL1-era code without sampler objects): a buffer's
    // (or Cube A's) filter is set on its texture object by each channel reading it, channel 0 to 3,
    // just before the draw, so in one pass the highest channel reading a texture decides the
    // filter for all of them. Wrap is set on both textures of a buffer when a channel reading it is
    // created, so the last such channel of the whole shader decides it (manifest/BufferWraps.h).
    const BufferWraps lastWrap = siteBufferWraps(manifest);
    for (PassPlan& pass : graph.passes)
        for (int c = 0; c < kChannelCount; ++c) {
            ChannelPlan& low = pass.channels[c];
            if (low.kind != ChannelKind::Buffer && low.kind != ChannelKind::CubeBuffer) continue;
            for (int d = kChannelCount - 1; d > c; --d) {
                const ChannelPlan& high = pass.channels[d];
                if (high.kind == low.kind && high.buffer == low.buffer && high.age == low.age) {
                    low.sampler.filter = high.sampler.filter;
                    break;
                }
            }
        }
    for (size_t i = 0; i < graph.passes.size(); ++i)
        for (int c = 0; c < kChannelCount; ++c)
            graph.passes[i].channels[c].sampler.wrap = wrapSampled(lastWrap, manifest.passes[i].channels[c]);
    return graph;
}

bool operator==(const ChannelPlan& a, const ChannelPlan& b) {
    return a.kind == b.kind && a.buffer == b.buffer && a.age == b.age && a.sampler.filter == b.sampler.filter &&
           a.sampler.wrap == b.sampler.wrap && a.sampler.vflip == b.sampler.vflip;
}

bool PassGraph::sameStructure(const PassGraph& other) const {
    if (passes.size() != other.passes.size() || bufferUsed != other.bufferUsed ||
        bufferMipmapped != other.bufferMipmapped || cubeUsed != other.cubeUsed || cubeMipmapped != other.cubeMipmapped)
        return false;
    for (size_t i = 0; i < passes.size(); ++i)
        if (passes[i].id != other.passes[i].id || passes[i].targetBuffer != other.passes[i].targetBuffer ||
            passes[i].targetCube != other.passes[i].targetCube ||
            passes[i].channels != other.passes[i].channels)
            return false;
    return true;
}

}  // namespace toyhost
