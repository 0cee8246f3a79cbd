// ExpressionDepth: an estimate of how deep each statement's expression tree is, to warn where
// Chrome refuses a shader that Mesa compiles: WebGL's translator rejects expressions nested deeper
// than 256 (parentheses, calls, long sums). Pure text work over shader/GlslTokens; no GL needed.
#pragma once

#include <string_view>
#include <vector>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// The deepest statement of `code`: its estimated depth and 1-based line (0, 0 for none). Per
// nesting level (a parenthesis, a bracket, one argument) the depth adds the longest run of one
// operator precedence, one for each other precedence there, and the deepest nested level.
struct DeepestStatement {
    int depth = 0;
    int line = 0;
};
DeepestStatement deepestStatement(std::string_view code);

// Chrome's limit (ANGLE's MaxExpressionComplexity as Chrome sets it for WebGL).
constexpr int kSiteExpressionDepthLimit = 256;

// The longest chain of calls from an entry point (mainImage, mainSound, mainCubemap) through the
// functions `code` defines, counting the entry point and the site's main() that calls it, and the
// line of the entry point's definition; 0, 0 when there is no entry point. Functions are known by
// name (overloads count as one); a recursive cycle (which GLSL refuses anyway) ends a chain.
struct DeepestCallChain {
    int depth = 0;
    int line = 0;
};
DeepestCallChain deepestCallChain(std::string_view code);
// Chrome's limit on the call stack (ANGLE's MaxCallStackDepth as Chrome sets it for WebGL).
constexpr int kSiteCallDepthLimit = 256;

// One warning per pass (Common included) with a statement deeper than the limit, and per pass
// (with Common's functions) whose calls nest deeper than the call limit: "the site refuses this".
// Warnings, not errors: the estimates are not ANGLE's exact counts.
std::vector<Diagnostic> deepExpressionWarnings(const ManifestDesc& manifest);

}  // namespace toyhost
