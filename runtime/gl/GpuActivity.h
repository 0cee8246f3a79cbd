// GpuActivity: what one GL context's GPU work is, published for a watchdog (core/RunActivity.h):
// the pass compiling, the pass the GPU is still drawing, a wait for a decoder or for the encoders.
// Every GlContext has one (GlContext::gpuActivity()); whoever watches the run attaches its
// RunActivity to the context, and everything that renders or waits on that context publishes
// itself: the renderer around its draws, readbacks and glFinish, queued reads around their map.
// Nobody publishes on a caller's behalf. Needs its context current for every call but attach()
// and activity(); the draws' fences are released with clear() (the context current).
#pragma once

#include <array>
#include <cstddef>

#include "core/RunActivity.h"

namespace toyhost {

class GpuActivity {
public:
    GpuActivity() = default;
    GpuActivity(const GpuActivity&) = delete;
    GpuActivity& operator=(const GpuActivity&) = delete;
    // The fences are not deleted here: the context that owns them may already be gone (they go
    // with it). clear() first where the context lives on.
    ~GpuActivity() = default;

    // Where to publish (null: nowhere) and whether draws are followed (a frame limit is set): a
    // fence follows each pass's draw, so that a wait names the pass the GPU is still drawing.
    // Nothing waits for those fences.
    void attach(RunActivity* activity, bool watchDraws);
    // The attached activity, for phases without the GPU (a decoder, the encoders); may be null.
    RunActivity* activity() const { return activity_; }

    // A pass's compile, published as Compiling until the object goes.
    class Compiling {
    public:
        Compiling(GpuActivity& gpu, const char* pass);
        ~Compiling();
        Compiling(const Compiling&) = delete;
        Compiling& operator=(const Compiling&) = delete;

    private:
        GpuActivity& gpu_;
    };
    // Around a call that may wait for the GPU (a readback, a mapped buffer, glFinish): the pass
    // the GPU is still drawing is published when it starts, and again (or idle) when it ends.
    class Wait {
    public:
        explicit Wait(GpuActivity* gpu);
        ~Wait();
        Wait(const Wait&) = delete;
        Wait& operator=(const Wait&) = delete;

    private:
        GpuActivity* gpu_;
    };

    // Right before and right after a pass's draw call. llvmpipe compiles a shader's machine code
    // lazily inside the first draw that uses it, which can take minutes (a huge local array), so
    // the call itself is published as DrawCall of its pass; once it returns, the oldest pass the
    // GPU still draws is published again (this one, timed from its call, when nothing is older).
    void beforeDraw(const char* pass, int frame);
    void afterDraw(const char* pass, int frame);
    // Around one of a frame's several draws of a pass and what goes with it (supersampling, motion
    // blur: timing/SamplePattern.h), `sample` (0-based) of `samples`. When draws are followed, the
    // draws before the first sample are waited for (published as usual), and each sample is
    // published from its call until the GPU has drawn it (afterSample waits): a frame limit bounds
    // each sample's draw, not the frame's sum of them (issue 44).
    void beforeSample(const char* pass, int frame, int sample, int samples);
    void afterSample();
    // The watching watchdog has ended the run (RunActivity::cancel): draw no more samples.
    bool cancelled() const { return activity_ && activity_->cancelled(); }
    // Forgets the passes that have finished (asking without waiting) and publishes the oldest one
    // still drawing (keeping its start time when it was already the one published), or idle.
    void publishPending();
    // Something else was published meanwhile (a wait for a video): publishPending() says it again.
    void forgetPublished() { published_ = nullptr; }
    // Deletes every fence (the context current): a renderer that goes takes its draws along.
    void clear();

private:
    struct Item {
        void* fence = nullptr;  // a GLsync
        const char* pass = "";
        int frame = 0;
    };
    void dropAll();
    void dropOldest();
    void waitFor(void* fence);  // blocks until the GPU passed `fence`

    RunActivity* activity_ = nullptr;
    bool watchDraws_ = false;
    // Oldest first; about three frames of six passes (an older one is forgotten when full).
    std::array<Item, 24> items_{};
    std::size_t count_ = 0;
    void* published_ = nullptr;  // compared only, never used after its deletion
    RunActivity::Snapshot beforeCall_;  // what was published when the current draw call began
};

}  // namespace toyhost
