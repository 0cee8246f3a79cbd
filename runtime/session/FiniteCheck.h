// FiniteCheck: reports, once per pass, a buffer that holds NaN or Inf (which spreads through
// feedback and shows as black in the Image) with the first frame it was seen in. Fed with float
// pixels the run already has (captured EXR frames, the end-of-run check) or, with
// --check-finite, a readback of every buffer after every frame. No GL needed.
#pragma once

#include <optional>
#include <span>

#include "core/Diagnostic.h"
#include "image/ImageStats.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

class FiniteCheck {
public:
    // Which frames were looked at before this one, so the message says how far to trust the frame.
    enum class Coverage { EveryFrame, CapturedFrames, LastFrameOnly };

    // A warning the first time `pass` is seen holding non-finite values in `found` at iFrame
    // `frame`; nothing when it is clean or was reported already.
    std::optional<Diagnostic> check(PassId pass, int frame, const NonFiniteFind& found, Coverage coverage);
    std::optional<Diagnostic> check(PassId pass, int frame, std::span<const float> rgba, int width, Coverage coverage) {
        return check(pass, frame, findNonFinite(rgba, width), coverage);
    }
    bool reported(PassId pass) const { return reported_[static_cast<int>(pass)]; }

private:
    bool reported_[static_cast<int>(PassId::Sound) + 1] = {};
};

}  // namespace toyhost
