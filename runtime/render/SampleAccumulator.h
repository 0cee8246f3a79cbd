// SampleAccumulator: the average of several draws of the Image pass (supersampling, motion blur:
// timing/SamplePattern.h). Each draw renders into a float target of its own (never rounded to 8
// bits), is added in float to a running sum (two RGBA32F textures, one read while the other is
// written: no float blending needed), and the average is written into the Image target, quantised
// once (an 8-bit target rounds it; an optional ordered dither before). Everything stays on the GPU.
// Needs a current GL context.
#pragma once

#include <array>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "render/RenderTargets.h"

namespace toyhost {

// How the draws are averaged into an 8-bit Image (a float Image, EXR, averages the raw floats).
struct SampleAverage {
    // True: in linear light (each draw's output, clamped to [0, 1] as the site shows it, decoded
    // from sRGB, averaged, encoded again), as a film renderer or a camera adds light. False: the
    // display values averaged as they are (the site's pixels box-filtered).
    bool linear = true;
    // An 8x8 ordered dither of +-0.5/255 added before the target rounds to 8 bits.
    bool dither = false;
    // The Image target is float: the raw outputs are averaged (no clamp, no decoding, no dither).
    bool floatTarget = false;
};

class SampleAccumulator {
public:
    static Result<SampleAccumulator> create(int width, int height, SampleAverage average,
                                            const TextureAllocator& allocate);

    // Where each draw of the Image pass renders (RGBA32F, width x height).
    unsigned int sampleFramebuffer() const { return sample_.framebuffer.id(); }
    // Copies `canvas` (the Image target's texture, width x height) into the sample target: an Image
    // that may `discard` leaves those pixels as the site's preserved canvas has them, so a draw
    // that discards adds the canvas's pixel, not an earlier draw's.
    void seed(unsigned int canvas);
    // Adds the draw in the sample target to the sum; the first draw of a frame starts it. The
    // caller has bound a vertex array for the full-screen triangle and set the viewport.
    void add(bool first);
    // Writes the average of `count` draws into `framebuffer` (the Image target).
    void resolve(unsigned int framebuffer, int count);

    // New size (the sum is per frame: nothing carries over). On failure nothing changed.
    Status resize(int width, int height, const TextureAllocator& allocate);

private:
    struct Programs {
        GlProgram add, resolve;
        int addSample = -1, addSum = -1, addFirst = -1, addMode = -1;
        int resolveSum = -1, resolveScale = -1, resolveDither = -1, resolveMode = -1;
    };
    struct Targets {
        RenderTexture sample;
        std::array<RenderTexture, 2> sums;
    };
    SampleAccumulator() = default;
    static Result<Targets> makeTargets(int width, int height, const TextureAllocator& allocate);
    int mode() const;  // the shaders' toyhostMode

    RenderTexture sample_;
    std::array<RenderTexture, 2> sums_;
    int current_ = 0;  // the slot holding the sum so far
    SampleAverage average_;
    Programs programs_;
};

}  // namespace toyhost
