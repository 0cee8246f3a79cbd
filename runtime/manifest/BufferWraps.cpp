#include "manifest/BufferWraps.h"

#include <algorithm>
#include <vector>

namespace toyhost {

namespace {

std::optional<int> slotOf(const ChannelDesc& channel) {
    if (channel.kind == ChannelKind::Buffer && channel.buffer >= 0 && channel.buffer < kBufferCount) return channel.buffer;
    if (channel.kind == ChannelKind::CubeBuffer) return kBufferCount;
    return std::nullopt;
}

}  // namespace

BufferWraps siteBufferWraps(const ManifestDesc& manifest) {
    struct Created {
        int pass, passOrder, channel, channelOrder;
    };
    std::vector<Created> created;
    for (size_t i = 0; i < manifest.passes.size(); ++i) {
        const PassDesc& pass = manifest.passes[i];
        const int passOrder = pass.listedAt >= 0 ? pass.listedAt : static_cast<int>(i);
        for (int c = 0; c < kChannelCount; ++c)
            created.push_back({static_cast<int>(i), passOrder, c, pass.channels[c].listedAt >= 0 ? pass.channels[c].listedAt : c});
    }
    std::stable_sort(created.begin(), created.end(), [](const Created& a, const Created& b) {
        return a.passOrder != b.passOrder ? a.passOrder < b.passOrder : a.channelOrder < b.channelOrder;
    });
    BufferWraps wraps;
    for (const Created& at : created) {
        const ChannelDesc& channel = manifest.passes[at.pass].channels[at.channel];
        if (const std::optional<int> slot = slotOf(channel)) wraps[*slot] = channel.sampler.wrap;
    }
    return wraps;
}

Wrap wrapSampled(const BufferWraps& wraps, const ChannelDesc& channel) {
    const std::optional<int> slot = slotOf(channel);
    return slot && wraps[*slot] ? *wraps[*slot] : channel.sampler.wrap;
}

}  // namespace toyhost
