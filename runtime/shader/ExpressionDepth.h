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

// One warning per pass (Common included) with a statement deeper than the limit: "the site
// refuses this". A warning, not an error: the estimate is not ANGLE's exact count.
std::vector<Diagnostic> deepExpressionWarnings(const ManifestDesc& manifest);

}  // namespace toyhost
