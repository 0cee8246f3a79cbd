#include "timing/SamplePattern.h"

#include <cstdint>
#include <numeric>

#include "timing/FrameClock.h"

namespace toyhost {

namespace {

// splitmix64: a fixed, platform-independent sequence (std's distributions are not).
std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// A permutation of 0..count-1 fixed by `part` (Fisher-Yates with mix()): which sub-stratum of
// part `part` each offset takes. The modulo's bias (count <= 256 against 2^64) is immaterial.
std::vector<int> permutation(int count, int part) {
    std::vector<int> order(static_cast<std::size_t>(count));
    std::iota(order.begin(), order.end(), 0);
    std::uint64_t state = mix(static_cast<std::uint64_t>(part) * 0x100000001b3ull + static_cast<std::uint64_t>(count));
    for (int i = count - 1; i > 0; --i) {
        state = mix(state);
        const int j = static_cast<int>(state % static_cast<std::uint64_t>(i + 1));
        std::swap(order[static_cast<std::size_t>(i)], order[static_cast<std::size_t>(j)]);
    }
    return order;
}

}  // namespace

std::optional<ShutterOffset> parseShutterOffset(std::string_view word) {
    if (word == "open") return ShutterOffset::Open;
    if (word == "centre" || word == "center") return ShutterOffset::Centre;
    if (word == "close") return ShutterOffset::Close;
    return std::nullopt;
}

std::optional<bool> parseSampleSpaceLinear(std::string_view word) {
    if (word == "linear") return true;
    if (word == "display") return false;
    return std::nullopt;
}

bool isSingleSample(const SamplingDesc& desc) { return desc.supersample == 1 && desc.motionBlur == 1; }

std::vector<SamplePoint> samplePattern(const SamplingDesc& desc) {
    std::vector<SamplePoint> points;
    const int n = desc.supersample, s = desc.motionBlur, cells = n * n;
    points.reserve(static_cast<std::size_t>(cells) * s);
    const double open = desc.shutterDegrees / 360.0;
    const double start = desc.shutterOffset == ShutterOffset::Open     ? 0.0
                         : desc.shutterOffset == ShutterOffset::Centre ? -open / 2
                                                                       : -open;
    const double strata = static_cast<double>(cells) * s;
    for (int k = 0; k < s; ++k) {
        const std::vector<int> order = permutation(cells, k);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                SamplePoint p;
                p.offset = glm::vec2(static_cast<float>((i + 0.5) / n - 0.5), static_cast<float>((j + 0.5) / n - 0.5));
                // The midpoint of the draw's own stratum: the average of the N^2 S samples of a
                // quantity linear in time is its average over the interval.
                const int stratum = k * cells + order[static_cast<std::size_t>(j * n + i)];
                p.fraction = s == 1 ? 0.0 : start + (stratum + 0.5) / strata * open;
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
