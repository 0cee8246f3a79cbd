// toyhost_frame_measures: prints FrameMeasures.h's numbers for consecutive PNG frames of one run
// (docs/gallery.md's before/after table is made with it). CPU only; a test-support tool, not a
// product CLI.
#include <cstdio>
#include <vector>

#include "FrameMeasures.h"
#include "image/ImageFile.h"

int main(int argc, char** argv) {
    using namespace toyhost;
    if (argc < 3) {
        std::fprintf(stderr, "usage: toyhost_frame_measures FRAME.png FRAME.png [...] (consecutive frames)\n");
        return 2;
    }
    std::vector<Image8> frames;
    for (int i = 1; i < argc; ++i) {
        auto image = loadImageFile(argv[i]);
        if (!image.ok()) {
            std::fprintf(stderr, "%s\n", image.error().text().c_str());
            return 1;
        }
        frames.push_back(std::move(*image));
    }
    const auto shimmer = testing::measureShimmer(frames);
    const Image8& f = frames.front();
    const int nearTop = f.height - f.height * 15 / 100;
    double clipped = 0.0;
    int black = 255;
    for (const auto& frame : frames) {
        clipped = std::max(clipped, testing::clippedShare(frame, std::max(shimmer.horizon, 0)));
        black = std::min(black, testing::blackLevel(frame));
    }
    std::printf("horizon_row %d band %.2f near %.2f shimmer_ratio %.2f clipped_pct %.3f black %d near_colours %d\n",
                shimmer.horizon, shimmer.band, shimmer.near, shimmer.ratio(), clipped * 100.0, black,
                testing::distinctCodeValues(f, nearTop, f.height, f.width / 4, 3 * f.width / 4));
    return 0;
}
