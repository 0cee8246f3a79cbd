#include "timing/SamplePattern.h"

#include "timing/FrameClock.h"

namespace toyhost {

bool isSingleSample(const SamplingDesc& desc) { return desc.supersample == 1 && desc.motionBlur == 1; }

std::vector<SamplePoint> samplePattern(const SamplingDesc& desc) {
    std::vector<SamplePoint> points;
    const int n = desc.supersample, s = desc.motionBlur;
    points.reserve(static_cast<std::size_t>(n) * n * s);
    const double open = desc.shutterDegrees / 360.0;
    for (int k = 0; k < s; ++k) {
        // The midpoints of S equal parts of the open interval: the average of S samples of a
        // quantity linear in time is its average over the interval.
        const double fraction = s == 1 ? 0.0 : (k + 0.5) / s * open;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                SamplePoint p;
                p.offset = glm::vec2(static_cast<float>((i + 0.5) / n - 0.5), static_cast<float>((j + 0.5) / n - 0.5));
                p.fraction = fraction;
                points.push_back(p);
            }
    }
    return points;
}

FrameTime subFrameTime(const FrameTime& frame, double fraction) {
    if (fraction == 0) return frame;
    FrameTime t = frame;
    const double later = fraction * frame.timeDelta;
    t.time = frame.time + later;
    if (frame.wallClock) {
        t.wallClock = *frame.wallClock + later;
        t.date = dateAt(*t.wallClock);
    } else {
        t.date.w = static_cast<float>(frame.date.w + later);  // seconds since midnight
    }
    return t;
}

}  // namespace toyhost
