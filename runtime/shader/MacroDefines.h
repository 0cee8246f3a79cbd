// MacroDefines: the `--define NAME[=VALUE]` macros a run adds to every pass (variants and
// parameter sweeps without editing the shadertoy's files): parsed and checked once, then written
// as #define lines after the site's header, before Common and the pass code. Pure text; no GL.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/Result.h"

namespace toyhost {

struct MacroDefine {
    std::string name;
    std::string value;  // "NAME" alone defines NAME as 1, as a C compiler's -D does
    bool operator==(const MacroDefine&) const = default;
};

using MacroDefines = std::vector<MacroDefine>;

// "NAME" or "NAME=VALUE". NAME is a GLSL identifier that GLSL ES does not reserve (no "GL_"
// prefix, no "__", not "defined"); VALUE is one line of GLSL's character set that leaves the
// line after its #define alone (no trailing '\', no comment left open) and holds no '#'. Errors
// name the setting "defines".
Result<MacroDefine> parseMacroDefine(std::string_view text);
// Every entry of `texts`; a name given twice with different values is refused (GLSL ES refuses a
// redefinition too), given twice alike it is kept once.
Result<MacroDefines> parseMacroDefines(std::span<const std::string> texts);

// The #define lines, each ending with a newline; empty for no defines.
std::string macroDefineLines(std::span<const MacroDefine> defines);

}  // namespace toyhost
