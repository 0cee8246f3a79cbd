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

// A lower bound of the depth of ANGLE's tree (the root block at 0) at the deepest statement of
// `code` (line as above): the levels surely above the statement (the function and its body; a
// declaration and its initialisation), then a leaf is 1 and an operation (a binary or unary
// operator, an assignment, a call, an index, a member) one more than its deepest operand; an
// operation on constants alone is one constant, as ANGLE folds it while parsing (literals, `const`
// names, macros, calls and constructors of constants); parentheses are no level; a constant
// condition keeps the shallower branch; what it cannot read counts nothing. Where this passes the
// limit below, Chrome refuses the shader (headless Chromium 156: `float v = ` 251 nested products
// of a variable compiles, 252 does not; as an assignment `v = `, 252 and 253).
DeepestStatement deepestStatementAtLeast(std::string_view code);

// Chrome's limit (ANGLE's MaxExpressionComplexity as Chrome sets it for WebGL): a tree deeper than
// this is refused.
constexpr int kSiteExpressionDepthLimit = 256;

// The longest chain of calls from an entry point (mainImage, mainSound, mainCubemap) through the
// functions `code` defines, counting the entry point and the site's main() that calls it, and the
// line of the entry point's definition; 0, 0 when there is no entry point. Functions are known by
// name (overloads count as one); a recursive cycle (which GLSL refuses anyway) ends a chain.
struct DeepestCallChain {
    int depth = 0;
    int line = 0;
    bool exact = false;  // no function along the chain is overloaded: the depth is the real one
};
DeepestCallChain deepestCallChain(std::string_view code);
// Chrome's limit on the call stack (ANGLE's MaxCallStackDepth as Chrome sets it for WebGL).
constexpr int kSiteCallDepthLimit = 256;

// Per pass (Common included), the site's verdict on depth. An error ("the site refuses this")
// where the lower bound of a statement's depth or an exact call chain passes the limit: Chrome
// refuses those shaders, so toyhost does too. A warning ("the site may refuse this") where only
// the estimate does, or a chain through overloads. The public and wild corpus (405 passes) stay
// far below both.
std::vector<Diagnostic> siteDepthProblems(const ManifestDesc& manifest);

}  // namespace toyhost
