// BrowserPreprocess: expands an assembled shader's preprocessor directives the way a browser's
// translator does, for the few shaders whose text Mesa's GLSL preprocessor rejects and WebGL
// accepts: a macro argument such as `-.7071` pasted after a `-` (Mesa re-reads the text and sees
// `--`; browsers keep the tokens apart), and `#if` inside a macro's arguments (Mesa: a syntax
// error; browsers evaluate it). Uses GCC's C preprocessor (Debian's `cpp`), which works on tokens
// and allows directives in macro arguments, with GLSL's predefined macros; the expanded text keeps
// every line where it was (#line), so compiler messages still name the user's lines. Only run
// when the driver's own compile failed: once per failed compile, never per frame. No GL needed.
#pragma once

#include <string>
#include <string_view>

#include "core/Result.h"

namespace toyhost {

// The expanded text of a GLSL ES 3.00 shader (`#version` first), or an error when `cpp` is missing
// or rejects the text, or when the text uses what GLSL ES forbids and C allows (browsers and Mesa
// refuse it): token pasting `##`, a macro name beginning with GL_ (#define, #undef), a macro
// defined again with another body, an undefined name in an #if or #elif that is evaluated. `#version`, `#extension` and `#pragma` lines are kept as they are.
Result<std::string> preprocessLikeBrowsers(std::string_view shader);

// `text` with every directive whose name is not GLSL's (`#elseif 1`, a typo of `#elif`) written as
// `#error invalid directive elseif 1`, on its line. C's rule, which browsers follow: in a group
// skipped by a conditional only conditional directives are read, so the browser ignores such a
// line there and refuses it elsewhere. Mesa's preprocessor reads it in a skipped group too
// (`#elseif` as `#else` then `if`: "syntax error, unexpected IDENTIFIER, expecting NEWLINE");
// `#error` is ignored in a skipped group and refuses the shader elsewhere, as the browser does.
// Pure text work, done on every pass's text (shader/ShaderAssembly.cpp).
std::string neutraliseUnknownDirectives(std::string_view text);

}  // namespace toyhost
