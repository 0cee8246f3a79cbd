#include "session/FiniteCheck.h"

#include <string>

namespace toyhost {

std::optional<Diagnostic> FiniteCheck::check(PassId pass, int frame, const NonFiniteFind& found, Coverage coverage) {
    if (found.count() == 0 || reported_[static_cast<int>(pass)]) return std::nullopt;
    reported_[static_cast<int>(pass)] = true;
    Diagnostic d;
    d.severity = Severity::Warning;
    d.code = Code::BufferNonFinite;
    d.pass = passName(pass);
    std::string what;
    if (found.nan) what += std::to_string(found.nan) + " NaN";
    if (found.inf) what += std::string(what.empty() ? "" : " and ") + std::to_string(found.inf) + " Inf";
    d.message = "holds non-finite values at iFrame " + std::to_string(frame) + " (" + what + ", the first at pixel " +
                std::to_string(found.x) + "," + std::to_string(found.y) + " ." + "rgba"[found.channel] + ")" +
                (coverage == Coverage::EveryFrame       ? "; every frame before was finite"
                 : coverage == Coverage::CapturedFrames ? "; the frames captured before were finite, the others were "
                                                          "not checked (--check-finite checks every frame)"
                                                        : "; earlier frames were not checked (--check-finite finds "
                                                          "the first)") +
                ". They spread through feedback and show as black; look for a division by zero, sqrt or "
                "log of a negative number, or pow with a negative base";
    return d;
}

}  // namespace toyhost
