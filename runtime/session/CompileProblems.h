// CompileProblems: a run that cannot start because of its inputs (an image that does not decode, a
// missing stock file) still compiles its passes, so that one run reports every problem: the two
// bad textures and the two passes that do not compile together, not one stage at a time. Needs
// to create a headless GL context (only on this failure path).
#pragma once

#include "core/Result.h"
#include "session/SessionOptions.h"

namespace toyhost {

// `failure` (prepareSession's error for `options`) plus the compile errors of every pass, when the
// shadertoy itself loads and the failure was not a usage error or a problem of the code's text.
Error withCompileProblems(const SessionOptions& options, Error failure);

}  // namespace toyhost
