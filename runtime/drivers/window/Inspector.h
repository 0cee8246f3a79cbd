// Inspector: the window's F2 panel, part of its overlay (drivers/window/Overlay.h): iTime, iFrame,
// the measured frame rate, iResolution, iMouse and the paused state; a thumbnail of every buffer
// and of the Image; a click on one shows that pass full-canvas (scaled to the window, NaN and
// infinite texels in magenta) with the float RGBA under the cursor, read back from the pass's own
// target; a click on the canvas then reports that texel as a notice. Nothing of it reaches a
// captured frame: it only reads pass outputs and draws on the window's default framebuffer.
// Needs the window's GL context current, inside an ImGui frame.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/Diagnostic.h"
#include "manifest/ManifestDesc.h"

namespace toyhost {

class SessionCore;

// What the window's clock says, for the panel.
struct InspectorClock {
    double time = 0;                  // iTime of the frame shown
    std::optional<double> frameRate;  // measured frames per second; empty until measured
    bool paused = false;
};

class Inspector {
public:
    void toggle() { open_ = !open_; }
    bool open() const { return open_; }

    // Draws the panel (and the shown pass over the canvas) into the current ImGui frame; a click on
    // a pass or on a texel adds a notice to `notices`. `framebufferW` x `framebufferH`: the window's.
    void draw(SessionCore& session, const InspectorClock& clock, int framebufferW, int framebufferH,
              std::vector<Diagnostic>& notices);

private:
    bool open_ = false;
    std::optional<PassId> shown_;  // the pass shown full-canvas; empty: the canvas as usual
};

// The RGBA of texel (x, y) (bottom-left origin) of a pass's latest output, as floats (an RGBA8
// target's bytes / 255). Reads one texel synchronously.
std::array<float, 4> readTexel(const SessionCore& session, PassId pass, int x, int y);

}  // namespace toyhost
