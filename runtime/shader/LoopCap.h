// LoopCap: finds `for` loops whose constant bounds pass llvmpipe's limit on loop iterations, so a
// run can say that Mesa stops them where the browser runs them all. Pure text work over
// shader/GlslTokens; no GL needed.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "manifest/ManifestDesc.h"

namespace toyhost {

// llvmpipe's limit (Mesa's gallivm LP_MAX_TGSI_LOOP_ITERATIONS, a compile-time constant with no
// environment variable or driconf option): one counter per invocation, shared by every loop that
// is not unrolled, ends them all after 65535 iterations in total. A 100,000-iteration loop counts
// 65535, a nested 300 x 300 65097, and a later loop of the same pixel runs once. Browsers run them
// all (tests/gl/test_loop_cap.cpp).
inline constexpr std::int64_t kLlvmpipeLoopIterations = 65535;

// A `for` loop whose iterations are known from its text.
struct CountedLoop {
    int line = 0;                // 1-based, of the `for`
    std::int64_t iterations = 0; // of this loop alone, per run of the loop
    std::int64_t total = 0;      // with the loops around it: iterations of this loop and of them all
};

// Every loop `for ([int|uint|float] i = A; i <op> B; i++ | i-- | ++i | --i | i += C | i -= C)`
// (op one of < <= > >= !=) whose A, B and C are constants (literals, `const` names declared once,
// object-like `#define NAME number`, and + - * / and parentheses of them). `total` counts the
// iterations of the loops it is nested in (those of them that are counted) as llvmpipe does: each
// iteration of each loop.
std::vector<CountedLoop> countedLoops(std::string_view code);

// Per pass (Common included), a warning ([shader.compile], "llvmpipe's loop cap: ...") at each
// loop whose total passes kLlvmpipeLoopIterations: the site runs all of them, toyhost (on Mesa's
// llvmpipe) stops there.
std::vector<Diagnostic> loopCapWarnings(const ManifestDesc& manifest);

}  // namespace toyhost
