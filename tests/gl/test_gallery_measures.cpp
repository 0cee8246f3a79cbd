// The gallery's measured bounds (issue 20), with tests/support/FrameMeasures.h over 4 frames of
// each port at 320x180, --fps 30 --start-time 3 (docs/gallery.md has the 640x360 numbers): the
// far-field shimmer ratio, the share of clipped pixels under the horizon, the black level where
// the scene has shadow, and that the dither is there. Bounds sit between today's numbers and the
// numbers before issue 20 (in comments), so a regression to the old behaviour fails.
#include <numeric>

#include "FrameMeasures.h"
#include "GalleryRender.h"
#include "GlTestSupport.h"

#include "image/ImageFile.h"

namespace toyhost::testing {
namespace {

namespace fs = std::filesystem;

// Frames 0..3 of `shadertoy` (with `edits` applied to a copy) at 320x180, 30 fps, from t = 3 s.
std::vector<Image8> renderFrames(const std::string& shadertoy, const std::string& name, const std::string& options = "",
                                 const std::vector<SourceEdit>& edits = {}) {
    const fs::path dir = freshOutputDir("gallery-measures/" + name);
    const fs::path folder = editedShadertoy(shadertoy, edits, dir);
    std::vector<Image8> frames;
    if (folder.empty()) return frames;
    auto run = runToyhost("run " + shellQuoted(folder) + " --size 320x180 --fps 30 --start-time 3 --frames 4 --quiet " +
                          options + " --out " + shellQuoted(dir / "f_%04d.png"));
    EXPECT_EQ(run.exitCode, 0) << run.output;
    for (int i = 0; i < 4; ++i) {
        char file[32];
        std::snprintf(file, sizeof file, "f_%04d.png", i);
        auto image = loadImageFile(dir / file);
        EXPECT_TRUE(image.ok()) << image.error().text();
        if (image.ok()) frames.push_back(std::move(*image));
    }
    return frames;
}

double worstClippedShare(const std::vector<Image8>& frames, int horizon) {
    double worst = 0.0;
    for (const Image8& f : frames) worst = std::max(worst, clippedShare(f, std::max(horizon, 0)));
    return worst;
}

struct PortBounds {
    const char* shadertoy;
    double maxShimmerRatio;  // band / near; 0: not checked (no horizon in view)
    double maxBand;          // band alone; 0: not checked
    int maxBlack;            // darkest luma; 255: not checked (no shadow in view)
    friend void PrintTo(const PortBounds& b, std::ostream* os) { *os << b.shadertoy; }
};

class GalleryMeasures : public ::testing::TestWithParam<PortBounds> {};

TEST_P(GalleryMeasures, WithinTheirBounds) {
    const PortBounds& b = GetParam();
    const auto frames = renderFrames(b.shadertoy, b.shadertoy);
    ASSERT_EQ(frames.size(), 4u);
    const Shimmer s = measureShimmer(frames);
    const double clipped = worstClippedShare(frames, s.horizon);
    int black = 255;
    for (const Image8& f : frames) black = std::min(black, blackLevel(f));
    std::printf("%s: horizon %d, band %.2f, near %.2f, ratio %.2f, clipped %.3f%%, black %d\n", b.shadertoy, s.horizon,
                s.band, s.near, s.ratio(), clipped * 100.0, black);
    EXPECT_LE(clipped, 0.005) << "clipped pixels under the horizon";
    if (b.maxShimmerRatio > 0) {
        EXPECT_GE(s.horizon, 0) << "no horizon found";
        EXPECT_LE(s.ratio(), b.maxShimmerRatio) << "far-field shimmer";
    }
    if (b.maxBand > 0) EXPECT_LE(s.band, b.maxBand) << "shimmer of the band under the horizon";
    EXPECT_LE(black, b.maxBlack) << "black level";
}

INSTANTIATE_TEST_SUITE_P(
    Gallery, GalleryMeasures,
    ::testing::Values(
        // before issue 20 at 320x180: ratio 4.70, clipped 0.03%; footprint filtering alone 2.3
        // (issue 20's goal: 1.5, met at 1.11 by a band that had gone flat, with the horizon found 9
        // rows low). Issue 29 samples the far band against the 16-sample truth instead (far band
        // 25 -> 33 dB at 640x360): 1.56, where the truth itself has 1.26.
        PortBounds{"exp-sine-ocean", 1.7, 0, 255},
        // before: ratio 2.28, clipped 2.1%, black 33 (issue 20's goal: ratio <= 1.5, met at 1.10 by
        // flattening the far water to a grey mirror). Issue 29 filters against the 16-sample truth
        // instead (far band 17 -> 30 dB, detail 0.5 -> 1.05): the far water moves again, 1.55 (1.60
        // with the band of samples stacked along the view).
        PortBounds{"raymarched-sea", 1.7, 0, 24},
        // before: band 5.87 (the goal: 0.6x of 5.7 = 3.4), black 39 (rock in shadow; the goal
        // and today: <= 10)
        PortBounds{"coastal-foam", 0, 3.4, 10},
        PortBounds{"lake-optics", 0, 0, 255},  // before: clipped 0.1%
        PortBounds{"caustics-pool", 0, 0, 255}, PortBounds{"ripple-pool", 0, 0, 255}),
    [](const auto& info) {
        std::string name = info.param.shadertoy;
        std::replace(name.begin(), name.end(), '-', '_');
        return name;
    });

// Looking down at exp-sine-ocean's smooth water: the dither adds code values to the 8-bit steps
// of the gradient (the image without it, by an edit, has clearly fewer colours in the same place).
TEST(GalleryDither, ExpSineOceanLookingDownIsDithered) {
    const std::string down = "--mouse 160,5";
    const auto dithered = renderFrames("exp-sine-ocean", "exp-sine-down", down);
    const auto plain = renderFrames("exp-sine-ocean", "exp-sine-down-plain", down,
                                    {{"image.glsl", "    return (a + b - 1.0) / 255.0;", "    return vec3(0.0);"}});
    ASSERT_EQ(dithered.size(), 4u);
    ASSERT_EQ(plain.size(), 4u);
    const Image8& d = dithered[0];
    const int top = d.height * 85 / 100;
    const int withDither = distinctCodeValues(d, top, d.height, d.width / 4, 3 * d.width / 4);
    const int without = distinctCodeValues(plain[0], top, d.height, d.width / 4, 3 * d.width / 4);
    std::printf("colours looking down: %d dithered, %d without\n", withDither, without);
    EXPECT_GE(2 * withDither, 5 * without) << "fewer than 2.5x the undithered colours";
}

// coastal-foam's wet rock reads as rock, not foam (issue 20): a copy of the port paints each pixel
// by what it shows (rock within 0.2 m above the water = wet, more than 1 m above = dry, foam
// cover over 0.6 = foam; a pixel of the far band takes two samples, and counts only when both
// show the same), and the same frame's luma is read there. Wet rock must be clearly
// darker than dry rock and almost never as bright as foam. Before: wet/dry 0.87 and 0.83,
// 2.0% and 1.8% of the wet pixels above luma 140.
TEST(GalleryMeasures, CoastalFoamWetRockIsDarkRockNotFoam) {
    const std::vector<SourceEdit> mask = {
        {"image.glsl", "    vec3 rockCol = vec3(0.0);\n", "    float cls = 4.0;\n    vec3 rockCol = vec3(0.0);\n"},
        {"image.glsl", "        float hw = waterH(p.xz, t, 3);",
         "        float hw = waterH(p.xz, t, 3);\n"
         "        cls = tr < 0.0 ? 4.0 : (p.y - hw < 0.2 ? 1.0 : (p.y - hw > 1.0 ? 0.0 : 4.0));"},
        {"image.glsl", "        foam *= fade;", "        foam *= fade;\n        cls = foam > 0.6 ? 2.0 : 3.0;"},
        {"image.glsl", "    return 1.0 - exp(-1.1 * col);           // gentle tone map",
         "    return vec3(float(cls == 1.0), float(cls == 0.0), float(cls == 2.0));"},
    };
    for (const char* name : {"coastal_foam_t2", "coastal_foam_mouse"}) {
        SCOPED_TRACE(name);
        const GalleryCase c = galleryCase(name);
        const auto frame = renderGalleryCase(c, freshOutputDir(std::string("gallery-measures/wet-rock/") + name));
        const auto classes =
            renderGalleryCase(c, freshOutputDir(std::string("gallery-measures/wet-rock-mask/") + name), mask);
        ASSERT_TRUE(frame && classes);
        auto image = loadImageFile(*frame);
        auto kind = loadImageFile(*classes);
        ASSERT_TRUE(image.ok() && kind.ok());
        double sum[3] = {0, 0, 0};
        int count[3] = {0, 0, 0}, wetBright = 0;
        for (int r = 0; r < image->height; ++r)
            for (int x = 0; x < image->width; ++x) {
                const std::size_t i = (static_cast<std::size_t>(image->height - 1 - r) * image->width + x) * 4;
                for (int k = 0; k < 3; ++k)
                    if (kind->rgba[i + k] > 240) {   // every sample of the pixel of that kind
                        const double luma = lumaAt(*image, x, r);
                        sum[k] += luma;
                        ++count[k];
                        if (k == 0 && luma > 140.0) ++wetBright;
                    }
            }
        ASSERT_GT(count[0], 200) << "too little wet rock in view";
        ASSERT_GT(count[1], 200) << "too little dry rock in view";
        ASSERT_GT(count[2], 200) << "too little foam in view";
        const double wet = sum[0] / count[0], dry = sum[1] / count[1], foam = sum[2] / count[2];
        const double brightShare = double(wetBright) / count[0];
        std::printf("%s: luma wet rock %.1f, dry rock %.1f, foam %.1f; wet above 140: %.2f%%\n", name, wet, dry, foam,
                    brightShare * 100.0);
        EXPECT_LE(wet, 0.8 * dry) << "wet rock is not darker than dry rock";
        EXPECT_LE(brightShare, 0.012) << "wet rock as bright as foam";
        EXPECT_LE(wet, 0.5 * foam);
    }
}

// ripple-pool does not pulse at 24 fps (issue 29): at 60 simulation steps a second a 24 fps frame
// takes 3, 2, 3, 2 ... steps; drawn from the last step alone, the picture changed by +-25% every
// other frame (median 29% between consecutive frames' changes, measured before the fix). The
// Image now interpolates between the last two steps. Over 48 frames of steady rain (frames 72-120,
// 3 s in), the change from one frame to the next varies by under 10% (median; the frames where a
// new drop lands are real events, a few of the 48); before the fix this fails.
// Both views: straight from above (TOP_VIEW, where it was measured) and the default 3-D view.
TEST(GalleryMeasures, RipplePoolDoesNotPulseAt24Fps) {
  for (const std::string view : {"top", "3d"}) {
    SCOPED_TRACE(view);
    const fs::path dir = freshOutputDir("gallery-measures/ripple-pool-24fps-" + view);
    const fs::path folder = editedShadertoy("ripple-pool", {{"common.glsl", "// #define RAIN ", "#define RAIN "}}, dir);
    ASSERT_FALSE(folder.empty());
    auto run = runToyhost("run " + shellQuoted(folder) + (view == "top" ? " --define TOP_VIEW" : "") + " --size 320x180 --fps 24 --frames 121 --quiet --out " +
                          shellQuoted(dir / "f_%04d.png"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::vector<Image8> frames;
    for (int i = 72; i <= 120; ++i) {
        char file[32];
        std::snprintf(file, sizeof file, "f_%04d.png", i);
        auto image = loadImageFile(dir / file);
        ASSERT_TRUE(image.ok()) << image.error().text();
        frames.push_back(std::move(*image));
    }
    std::vector<double> change;
    for (std::size_t i = 1; i < frames.size(); ++i)
        change.push_back(meanLumaChange(frames[i - 1], frames[i], 0, frames[i].height));
    std::vector<double> variation;
    for (std::size_t i = 1; i < change.size(); ++i) variation.push_back(std::abs(change[i] / change[i - 1] - 1.0));
    std::sort(variation.begin(), variation.end());
    const double median = variation[variation.size() / 2];
    std::printf("ripple-pool (%s) at 24 fps: mean change %.3f levels a frame, median variation %.1f%%\n", view.c_str(),
                std::accumulate(change.begin(), change.end(), 0.0) / change.size(), median * 100.0);
    ASSERT_EQ(change.size(), 48u);
    EXPECT_GT(change[0], 0.2) << "the rain does not move the water";
    EXPECT_LT(median, 0.10) << "the water pulses from frame to frame";
  }
}

}  // namespace
}  // namespace toyhost::testing
