// toyhost/Shards.h (public API, stable): how a render of N frames is split into shards, the one
// rule behind `toyhost run --shard i/n`, `toyhost farm plan` and Python's toyhost.farm (their
// frames fit together because they all split with it), and which frames a run captures (the
// capture-every rule its recordings, its renders into memory and `farm status` share). Plain
// arithmetic; no GL needed.
#pragma once

#include <toyhost/Export.h>
#include <toyhost/Result.h>

namespace toyhost {

// Frames first .. end - 1 of a run (by frame number, iFrame for a fixed-step run).
struct FrameSpan {
    int first = 0;
    int end = 0;
};

// Shard `index` (from 0) of `shards` equal contiguous parts of a run of `frames` frames: from
// frames * index / shards to frames * (index + 1) / shards, rounded down (computed without
// overflow), so the spans follow one another, cover every frame once and differ in length by one
// frame at most. A Code::Usage error unless 1 <= shards <= frames and 0 <= index < shards (so
// every shard has a frame).
TOYHOST_API Result<FrameSpan> shardSpan(int frames, int shards, int index);

// The capture-every rule: frame `frame` (iFrame) is captured when it is a multiple of `every`, or
// the last frame before `end` (0: no end).
inline bool capturedFrame(int frame, int end, int every) {
    return frame % every == 0 || (end > 0 && frame == end - 1);
}

}  // namespace toyhost
