// WindowTitle: what a window's title says (the shadertoy, the rate frames are shown at, iFrame and
// iTime of the shown frame, paused, stopping, the current problem) and ShownFrameRate, the rate it
// shows. Pure text and arithmetic on times passed in (tests/unit/test_window_title.cpp); no GL.
#pragma once

#include <optional>
#include <string>

namespace toyhost {

// "name | 59.6 fps | iFrame 120 | iTime 2.00 | problem"; while paused "name | iFrame 120 |
// iTime 2.00 | paused (F6)" (no rate: nothing is being rendered); after Esc "... | stopping (Esc
// again: at once)".
struct WindowTitle {
    std::string name;
    std::optional<double> frameRate;  // empty: not measured yet ("--")
    int shownFrame = -1;              // < 0: no frame shown yet
    double time = 0;
    bool paused = false;
    std::string problem;              // "" when none
    bool stopping = false;            // Esc or the close button: the run is completing its outputs
    bool operator==(const WindowTitle&) const = default;
};
std::string formatWindowTitle(const WindowTitle& title);

// The rate frames are rendered at while the window runs: frames over the running time of windows
// of more than half a second, the time spent paused left out (a window that spans a pause measures
// only the frames and time around it). Unlike iFrameRate (timing/SiteFrameRate.h, the site's
// counter, which counts across a pause), this is what the user asks the title: how fast does it
// run. Frames rendered while paused (a step, a frame forced by input) are not counted.
class ShownFrameRate {
public:
    explicit ShownFrameRate(double now) : windowStart_(now) {}

    void frame(double now);
    void setPaused(bool paused, double now);
    // Empty until the first window closed, and while paused.
    std::optional<double> rate() const;

    static constexpr double kWindowSeconds = 0.5;

private:
    double windowStart_;
    double pausedAt_ = 0;
    bool paused_ = false;
    int frames_ = 0;
    std::optional<double> rate_;
};

}  // namespace toyhost
