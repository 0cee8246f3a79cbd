// DrawFences: a fence after each frame submitted, and a wait until fewer than a given number of
// those frames are still being drawn: how a loop keeps the GPU's queue short (the memory frame
// stream's frames-ahead pacing, session/MemoryFrameStream.h). Needs its GL context current for
// every call and when it is destroyed or cleared.
#pragma once

#include <cstddef>
#include <deque>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "gl/GpuActivity.h"

namespace toyhost {

class DrawFences {
public:
    // `gpu`: the context's activity, where a wait publishes the pass the GPU is still drawing (the
    // watchdog's view); null: nothing is published.
    explicit DrawFences(GpuActivity* gpu = nullptr) : gpu_(gpu) {}

    // A fence after everything submitted so far (the frame just submitted).
    void submitted();
    // Waits until fewer than `count` fenced frames are still being drawn (forgetting the drawn
    // ones, oldest first). Errors name GL's.
    Status waitBelow(std::size_t count);
    // Fenced frames not yet seen drawn.
    std::size_t pending() const { return fences_.size(); }
    void clear() { fences_.clear(); }

private:
    GpuActivity* gpu_ = nullptr;
    std::deque<GlFence> fences_;  // oldest first
};

}  // namespace toyhost
