// FloatConstantFold: the browsers' values for the float built-in calls whose constant result
// ANGLE's front end decides itself, for every backend: a call with arguments GLSL leaves undefined
// is folded to 0, and round() rounds half away from zero. Mesa folds them to NaN, +-inf, pi, 1 or
// half to even. Pure text work over shader/GlslTokens; no GL needed.
#pragma once

#include <vector>

#include "shader/GlslTokens.h"
#include "shader/IntegerConstantFold.h"

namespace toyhost {

// For each call of a float built-in whose arguments this module can evaluate (float literals,
// `float()`/`vecN()` constructors of them, parentheses, unary `- +`, binary `+ - * /`, swizzles,
// names declared `const float`/`const vecN` once in the text, object-like macros whose body is one
// such operand, nested calls of the built-ins it knows), when ANGLE's folder gives it a value of
// its own (any component):
//   - log, log2 (x <= 0), sqrt (x < 0), inversesqrt (x <= 0), acosh (x < 1), atanh (|x| >= 1),
//     pow (x < 0, or x = 0 and y <= 0), atan(y, x) (both 0), normalize (length 0), smoothstep
//     (edge0 >= edge1), clamp (min > max): 0;
//   - round: half away from zero (C's roundf), where round-half-to-even differs;
// an edit that writes the call's whole value (`0.0`, `vec2(1.0, (-3.0))`) in place of the call, in
// code and in `#define` bodies (a macro's parameter is never a constant), and in place of the
// invocation of a function-like macro whose body is such a call (`#define R(x) round(x)`: `R(2.5)`).
// A value with an infinite or NaN component is not written. asin and acos are left to the
// preciseInverseTrig rule (shader/GlslRewrite.h). An edit nested in another is dropped.
std::vector<ConstantFoldEdit> foldAngleFloatBuiltins(const std::vector<GlslToken>& tokens);

}  // namespace toyhost
