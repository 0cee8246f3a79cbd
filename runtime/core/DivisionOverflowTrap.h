// DivisionOverflowTrap: while one lives, the x86-64 `idiv` of the most negative integer by -1 gives
// the browsers' answer (quotient INT_MAX, remainder 0) instead of killing the process with
// SIGFPE. Mesa's GLSL constant folder (22.3) divides with the host's `idiv`, so a shader holding
// `int(0x80000000u) / -1` in a constant expression crashed toyhost; browsers compile it, and
// ANGLE's folder saturates the quotient to INT_MAX (headless Chromium, ../shared/webref probes
// int_divzero_const and cp_const_intmin_div). Held around glCompileShader and glLinkProgram (gl/ShaderProgram.cpp): a
// shader must never end the process. Any other SIGFPE goes to the handler that was there before
// (by default: the process ends, as before). Elsewhere than x86-64 Linux it does nothing (ARM's
// sdiv does not trap). No GL.
#pragma once

namespace toyhost {

class DivisionOverflowTrap {
public:
    DivisionOverflowTrap();   // the first one alive installs the handler (thread-safe)
    ~DivisionOverflowTrap();  // the last one puts the previous handler back
    DivisionOverflowTrap(const DivisionOverflowTrap&) = delete;
    DivisionOverflowTrap& operator=(const DivisionOverflowTrap&) = delete;

    // How many divisions the handler has completed since the process started.
    static long emulated();
};

}  // namespace toyhost
