// Compiles and links a GL program from vertex and fragment shader text, returning the driver's
// own info log on failure (shader/CompilerLog.h turns it into the user's file and line). Needs a
// current GL context.
#pragma once

#include <string>

#include "gl/GlObjects.h"

namespace toyhost {

struct ProgramBuild {
    enum class Stage { Vertex, Fragment, Link };
    GlProgram program;  // valid only when ok
    bool ok = false;
    Stage failedStage = Stage::Fragment;
    std::string log;    // the driver's info log of the stage that failed
};

ProgramBuild buildProgram(const std::string& vertexText, const std::string& fragmentText);

}  // namespace toyhost
