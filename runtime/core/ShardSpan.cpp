// ShardSpan: toyhost::shardSpan (include/toyhost/Shards.h), the one split of a run into shards.
// Pure arithmetic; no GL.
#include <toyhost/Shards.h>

#include <string>

namespace toyhost {

Result<FrameSpan> shardSpan(int frames, int shards, int index) {
    if (shards < 1 || shards > frames || index < 0 || index >= shards)
        return Error("shard " + std::to_string(index) + " of " + std::to_string(shards) + " of " +
                         std::to_string(frames) + " frames: expected 0 <= index < shards <= frames",
                     Code::Usage);
    // 64-bit products: frames * shards passes 2^31 for long runs in many shards.
    return FrameSpan{static_cast<int>(static_cast<long long>(frames) * index / shards),
                     static_cast<int>(static_cast<long long>(frames) * (index + 1) / shards)};
}

}  // namespace toyhost
