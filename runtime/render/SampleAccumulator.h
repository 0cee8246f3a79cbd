// SampleAccumulator: the average of several draws of the Image pass (supersampling, motion blur:
// timing/SamplePattern.h). Each draw lands in the Image target as the site would show it (8 bits,
// or float for a float Image target); it is added in float to a running sum (two RGBA32F
// textures, one read while the other is written: no float blending needed), and the average is
// written back into the Image target, rounded to its format, optionally with an ordered dither
// first. Everything stays on the GPU. Needs a current GL context.
#pragma once

#include <array>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "render/RenderTargets.h"

namespace toyhost {

class SampleAccumulator {
public:
    static Result<SampleAccumulator> create(int width, int height, const TextureAllocator& allocate);

    // Adds `sample` (a width x height texture) to the sum; the first sample of a frame starts it.
    // The caller has bound a vertex array for the full-screen triangle and set the viewport.
    void add(unsigned int sample, bool first);
    // Writes sum / count into `framebuffer` (the Image target). With `dither`, an 8x8 ordered
    // dither of +-0.5/255 is added before the target rounds to 8 bits (gradients without bands).
    void resolve(unsigned int framebuffer, int count, bool dither);

    // New size (the sum is per frame: nothing carries over). On failure nothing changed.
    Status resize(int width, int height, const TextureAllocator& allocate);

private:
    struct Programs {
        GlProgram add, resolve;
        int addSample = -1, addSum = -1, addFirst = -1;
        int resolveSum = -1, resolveScale = -1, resolveDither = -1;
    };
    SampleAccumulator() = default;

    std::array<RenderTexture, 2> sums_;
    int current_ = 0;  // the slot holding the sum so far
    Programs programs_;
};

}  // namespace toyhost
