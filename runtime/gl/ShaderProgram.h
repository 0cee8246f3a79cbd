// Compiles and links a pass's program, turning compiler logs into messages that name the user's
// file and line. Needs a current GL context.
#pragma once

#include <string>

#include "core/Result.h"
#include "gl/GlObjects.h"
#include "shader/ShaderAssembly.h"

namespace toyhost {

struct ProgramSources {
    std::string passLabel;     // "Buffer A", used when the error has no line
    std::string passFile;      // shown for errors in the pass code
    std::string commonFile;    // shown for errors in Common
};

Result<GlProgram> buildProgram(const AssembledShader& fragment, const ProgramSources& names);

}  // namespace toyhost
