// OpaqueDivisors: the insertions that hide every divisor inside a function body from Mesa's
// constant folder (`a / b` -> `a / toyhost_opaque(b)`: b's bits XORed with a uniform 0), so that a
// division by a zero the compiler could see is computed at run time, as the browser's GPU does.
// Pure text work over shader/GlslTokens; no GL needed (the renderer sets the uniform).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "shader/GlslTokens.h"

namespace toyhost {

// The uniform uint the renderer sets to 0 once per program (render/ChannelBindings.h:
// setChannelUniforms), and the function that XORs a float divisor's bits with it: the same bits
// for every float, -0, inf and NaN included, so the division's value is the IEEE one of the user's
// text; only Mesa can no longer see the divisor's value. Not `x * uniform 1.0`: Mesa folds
// `0.0 * anything` to 0.0 (an inexact algebraic rule GLSL allows), which gave the constant zero
// back; `c ^ u` it folds only for c = 0, to u itself, whose value it does not know either.
inline constexpr const char* kZeroUniform = "toyhost_zero";
inline constexpr const char* kOpaqueFunction = "toyhost_opaque";

struct DivisorInsertion {
    std::size_t offset = 0;  // into the tokenized text; the text goes before the byte there
    std::string text;
    // `)`: goes after any other rule's insertion at the same offset (which belongs to what comes
    // next), where `toyhost_opaque(` goes before (`x / asin(y)`: `toyhost_opaque(toyhost_asin(y))`).
    bool closes = false;
};

// For each divisor inside a function body: the right operand of `/` (a unary expression), the
// right-hand side of `/=`, and the argument a built-in's lowering divides by (smoothstep's second
// edge: e1 - e0; mod's y: x - y * floor(x / y); atan(y, x)'s x; atanh's x: 1 - x; inverse's
// matrix: its determinant): `toyhost_opaque(` before it and `)` after it.
// Left alone: directives, code outside function bodies (global initialisers), `const`
// declarations, array sizes and indices (`[...]`), `case` labels (all must stay constant, and
// ANGLE folds them itself), a non-zero number literal (nothing to hide, and Mesa keeps turning
// `x / 2.0` into a product), a bare integer literal, and the integer operations
// shader/IntegerConstantFold rewrites. Integer divisors otherwise pass through an identity
// overload.
std::vector<DivisorInsertion> opaqueDivisors(const std::vector<GlslToken>& tokens);

// The header's `uniform uint toyhost_zero;` and the toyhost_opaque overloads (float and vectors
// through their bits, matrices column by column; int and uint types unchanged); empty when `user` (the tokenized
// text's source) has nothing opaqueDivisors would wrap.
std::string opaqueDivisorDeclarations(std::string_view user);

}  // namespace toyhost
