// libFuzzer target: any text through the pure analyses toyhost runs on users' shader text before
// GL sees it: the WebGL source rewrite (runtime/shader/GlslRewrite.h: zero initialisation, also of
// declarations made by macros, index clamps, also in macro bodies, renames, integer constant
// folding of scalars, vectors and macro operands, float built-in folding, precise asin/acos, opaque
// divisors, precision promotion; seeds/fuzz_shader_text/macros_and_folds.glsl), which promises every change
// stays on its line (the output has as many newlines as the input), and the depth checks
// (runtime/shader/ExpressionDepth.h), whose depths are never negative.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "shader/ExpressionDepth.h"
#include "shader/GlslRewrite.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    toyhost::GlslRewriteOptions options;
    options.lowp = options.mediump = size % 2 == 0;
    const std::string out = toyhost::rewriteLikeWebGL(text, options);
    if (std::count(out.begin(), out.end(), '\n') != std::count(text.begin(), text.end(), '\n')) std::abort();
    if (toyhost::deepestStatementAtLeast(text).depth < 0 || toyhost::deepestStatement(text).depth < 0 ||
        toyhost::deepestCallChain(text).depth < 0)
        std::abort();
    return 0;
}
