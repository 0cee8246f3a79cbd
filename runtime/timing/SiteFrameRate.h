// SiteFrameRate: iFrameRate as shadertoy.com computes it in real time (piLibs' FPS counter, which
// the site's render loop calls before each Paint and passes to the shader): 60 until more than
// half a second has passed since the counter started, then the frames counted in each window of
// more than 0.5 s divided by its length, updated when a window closes. The counter starts with
// the player and is not reset by a restart. Pure arithmetic on times passed in; no GL needed.
#pragma once

namespace toyhost {

class SiteFrameRate {
public:
    // `now`: monotonic seconds when the counter starts.
    explicit SiteFrameRate(double now) : windowStart_(now) {}

    // Counts a frame rendered at `now`; true when a window closed and the rate changed.
    bool count(double now) {
        ++frames_;
        if (now - windowStart_ <= kWindowSeconds) return false;
        rate_ = frames_ / (now - windowStart_);
        frames_ = 0;
        windowStart_ = now;
        measured_ = true;
        return true;
    }
    double rate() const { return rate_; }
    // False until the first window closed (rate() is then the site's starting 60).
    bool measured() const { return measured_; }

    static constexpr double kWindowSeconds = 0.5;
    static constexpr double kStartRate = 60.0;

private:
    double windowStart_;
    int frames_ = 0;
    double rate_ = kStartRate;
    bool measured_ = false;
};

}  // namespace toyhost
