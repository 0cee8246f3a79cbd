// TexelCornerReads: finds `texture()` reads of a linear-filtered buffer whose coordinates, built
// from fragCoord, floor(), integer vectors and the resolution, land where linear and nearest give
// different values (texel corners, or uv-space neighbour steps compared exactly). Pure text work
// over shader/GlslTokens; no GL needed.
#pragma once

#include <string_view>
#include <vector>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// Where one read lands, as far as the scan can tell from the pass's own text.
enum class TexelLanding {
    Corner,  // an integer number of texels / resolution: linear averages the four texels around it
    UvStep,  // a texel centre reached by adding an offset in uv units (uv + k / resolution): linear
             // carries the sum's float rounding (~1e-6 of a texel) into the value
};

struct TexelRead {
    int channel = 0;
    int line = 0;  // 1-based, in the scanned text
    TexelLanding landing = TexelLanding::Corner;
};

// Every texture()/textureLod() read of iChannelN in `code` whose coordinate the scan can follow
// and which lands on a corner or is a uv-space step. Reads at exact centres ((fragCoord + k) /
// resolution, (vec2(ivec) + 0.5) / resolution) and coordinates it cannot follow (function
// parameters other than fragCoord, anything scaled or warped) are not listed.
std::vector<TexelRead> texelReads(std::string_view code);

// True when `code` compares with == or != against a float literal: what makes a uv-space step's rounding
// change the picture (an automaton's `n == 3.0`); thresholds (step, >, round) absorb it.
bool comparesExactly(std::string_view code);

// One warning per pass and buffer channel whose filter is not nearest and which is read on
// corners, or by uv-space steps in a pass that compares exactly: the picture differs from the one
// nearest gives, which is what a pixel-exact shader (a cellular automaton) was written for.
std::vector<Diagnostic> texelCornerWarnings(const ManifestDesc& manifest);

}  // namespace toyhost
