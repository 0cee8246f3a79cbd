#include "timing/WindowTitle.h"

#include <cstdio>

namespace toyhost {

std::string formatWindowTitle(const WindowTitle& t) {
    std::string title = t.name.empty() ? std::string("toyhost") : t.name;
    if (t.shownFrame >= 0) {
        char text[96];
        // One decimal: a slow shader at 0.1 fps is not "0 fps".
        if (!t.paused) {
            if (t.frameRate) std::snprintf(text, sizeof text, " | %.1f fps", *t.frameRate);
            else std::snprintf(text, sizeof text, " | -- fps");
            title += text;
        }
        std::snprintf(text, sizeof text, " | iFrame %d | iTime %.2f", t.shownFrame, t.time);
        title += text;
    }
    if (t.stopping) title += " | stopping (Esc again: at once)";
    else if (t.paused) title += " | paused (F6)";
    if (!t.problem.empty()) title += " | " + t.problem;
    return title;
}

void ShownFrameRate::frame(double now) {
    if (paused_) return;
    ++frames_;
    const double elapsed = now - windowStart_;
    if (elapsed <= kWindowSeconds) return;
    rate_ = frames_ / elapsed;
    frames_ = 0;
    windowStart_ = now;
}

void ShownFrameRate::setPaused(bool paused, double now) {
    if (paused == paused_) return;
    if (paused) pausedAt_ = now;
    else windowStart_ += now - pausedAt_;  // the window goes on as if the pause had not been
    paused_ = paused;
}

std::optional<double> ShownFrameRate::rate() const { return paused_ ? std::nullopt : rate_; }

}  // namespace toyhost
