// FrameMeasures: the gallery's numbers from rendered 8-bit frames (issue 20): the horizon row, the
// far-field shimmer ratio (horizon band vs near field, frame to frame), the share of clipped
// pixels under the horizon, the black level and the distinct code values of a region. CPU only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <vector>

#include "image/Image.h"

namespace toyhost::testing {

// Rec. 709 luma of an 8-bit pixel, in levels 0..255. `row` counts from the TOP of the picture
// (Image8 stores the bottom row first).
inline double lumaAt(const Image8& image, int x, int rowFromTop) {
    const int y = image.height - 1 - rowFromTop;
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
    return 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
}

// Mean |luma(x+1) - luma(x)| along one row (from the top).
inline double rowDetail(const Image8& image, int rowFromTop) {
    double sum = 0.0;
    for (int x = 0; x + 1 < image.width; ++x)
        sum += std::abs(lumaAt(image, x + 1, rowFromTop) - lumaAt(image, x, rowFromTop));
    return image.width > 1 ? sum / (image.width - 1) : 0.0;
}

// The horizon: the first row from the top whose horizontal detail is 4x the sky's (the mean
// detail of the top 5% of rows, at least 0.25 levels so a flat sky does not make every row
// count). -1 when no row qualifies (no horizon in view).
inline int horizonRow(const Image8& image) {
    const int skyRows = std::max(1, image.height / 20);
    double sky = 0.0;
    for (int r = 0; r < skyRows; ++r) sky += rowDetail(image, r);
    sky = std::max(sky / skyRows, 0.25);
    for (int r = skyRows; r < image.height; ++r)
        if (rowDetail(image, r) >= 4.0 * sky) return r;
    return -1;
}

// Mean |luma difference| between two frames over the rows [top, bottom) from the top.
inline double meanLumaChange(const Image8& a, const Image8& b, int top, int bottom) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int r = std::max(top, 0); r < std::min(bottom, a.height); ++r)
        for (int x = 0; x < a.width; ++x, ++n) sum += std::abs(lumaAt(a, x, r) - lumaAt(b, x, r));
    return n ? sum / double(n) : 0.0;
}

struct Shimmer {
    int horizon = -1;     // row from the top (first frame), -1 when none is in view
    double band = 0.0;    // mean consecutive-frame luma change, 12% of the height under the horizon
    double near = 0.0;    // the same over the bottom 15% of rows
    double ratio() const { return near > 0.0 ? band / near : 0.0; }
};

// Over consecutive frames (same size, at a fixed frame rate). Without a horizon the band is the
// top 12% of the picture.
inline Shimmer measureShimmer(const std::vector<Image8>& frames) {
    Shimmer s;
    if (frames.size() < 2) return s;
    const Image8& first = frames.front();
    s.horizon = horizonRow(first);
    const int top = std::max(s.horizon, 0);
    const int band = std::max(1, int(std::lround(first.height * 0.12)));
    const int nearTop = first.height - std::max(1, int(std::lround(first.height * 0.15)));
    for (std::size_t i = 1; i < frames.size(); ++i) {
        s.band += meanLumaChange(frames[i - 1], frames[i], top, top + band);
        s.near += meanLumaChange(frames[i - 1], frames[i], nearTop, first.height);
    }
    s.band /= double(frames.size() - 1);
    s.near /= double(frames.size() - 1);
    return s;
}

// Share (0..1) of the pixels in rows [top, height) from the top with all of R, G and B at 255.
inline double clippedShare(const Image8& image, int top) {
    std::size_t clipped = 0, n = 0;
    for (int r = std::max(top, 0); r < image.height; ++r)
        for (int x = 0; x < image.width; ++x, ++n) {
            const std::size_t i = (static_cast<std::size_t>(image.height - 1 - r) * image.width + x) * 4;
            if (image.rgba[i] == 255 && image.rgba[i + 1] == 255 && image.rgba[i + 2] == 255) ++clipped;
        }
    return n ? double(clipped) / double(n) : 0.0;
}

// The black level: the darkest pixel's luma (levels, rounded).
inline int blackLevel(const Image8& image) {
    double lowest = 255.0;
    for (int r = 0; r < image.height; ++r)
        for (int x = 0; x < image.width; ++x) lowest = std::min(lowest, lumaAt(image, x, r));
    return int(std::lround(lowest));
}

// Distinct colours (RGB code-value triplets) over the rows [top, bottom) from the top and the columns
// [left, right): few values over a smooth gradient is banding.
inline int distinctCodeValues(const Image8& image, int top, int bottom, int left, int right) {
    std::set<int> values;
    for (int r = std::max(top, 0); r < std::min(bottom, image.height); ++r)
        for (int x = std::max(left, 0); x < std::min(right, image.width); ++x) {
            const std::size_t i = (static_cast<std::size_t>(image.height - 1 - r) * image.width + x) * 4;
            values.insert(image.rgba[i] << 16 | image.rgba[i + 1] << 8 | image.rgba[i + 2]);
        }
    return int(values.size());
}

}  // namespace toyhost::testing
