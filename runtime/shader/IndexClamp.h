// IndexClamp: the insertions that clamp every dynamic array, vector and matrix index of a GLSL text
// to [0, size - 1], as ANGLE does for WebGL (an index becomes int(clamp(float(i), 0.0, float(n)))).
// Every insertion stays inside its line. Pure text work over shader/GlslTokens; no GL needed.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "shader/GlslTokens.h"

namespace toyhost {

struct IndexInsertion {
    std::size_t offset = 0;  // into the tokenized text; the text goes before the byte there
    std::string text;
};

// For each `[...]` that indexes a variable whose type the text declares (a built-in scalar, vector
// or matrix type, or an array of any type, local, parameter or global, and iChannelResolution /
// iChannelTime), with an index that is not made of literals alone: an insertion after the `[` and
// one before the `]`. Indices of what it cannot type (a struct member, a swizzle, a function's
// result) and array sizes in declarations are left as they are. Constant indices are checked by
// the compiler, as in WebGL.
std::vector<IndexInsertion> clampDynamicIndices(const std::vector<GlslToken>& tokens);

}  // namespace toyhost
