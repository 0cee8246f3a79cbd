// The compatibility runner's pure parts (tools/compat/ProbeScript.h, FrameMeasure.h): the visitor's
// mouse never crosses the exact centre and is released before the last frame, which is judged
// after the release; a failure shows its first error line, not the warnings before it; a frame is
// degenerate when too few pixels differ from its dominant colour (one pixel or a faint haze is not
// a picture).
#include <gtest/gtest.h>

#include <cmath>

#include "../../tools/compat/FrameMeasure.h"
#include "../../tools/compat/ProbeScript.h"

using namespace toyhost;
using namespace toyhost::compat;

TEST(CompatProbeScript, TheMouseIsPressedDraggedOffCentreAndReleasedBeforeTheLastFrame) {
    const int frames = 10, w = 160, h = 90;
    bool down = false, released = false;
    int lastDownFrame = -1;
    for (int f = 0; f < frames; ++f)
        for (const InputEvent& e : probeMouseAt(f, frames, w, h)) {
            if (e.type == InputEvent::Type::MouseDown) down = true, lastDownFrame = f;
            if (e.type == InputEvent::Type::MouseUp) released = true, lastDownFrame = f;
            if (e.type != InputEvent::Type::MouseUp) {
                EXPECT_FALSE(e.x == w / 2.0f && e.y == h / 2.0f) << "frame " << f;
                EXPECT_TRUE(e.x >= 0 && e.x < w && e.y >= 0 && e.y < h);
            }
        }
    EXPECT_TRUE(down);
    EXPECT_TRUE(released);
    EXPECT_LT(lastDownFrame, frames - 1);  // the last frame is rendered with the button up
    // With more frames (patience), nothing happens after the release.
    for (int f = frames; f < 40; ++f) EXPECT_TRUE(probeMouseAt(f, frames, w, h).empty());
}

TEST(CompatProbeScript, TheFirstErrorLineIsShownNotTheWarningsBeforeIt) {
    EXPECT_EQ(firstErrorLine("0:3(1): warning: x unused\n0:4(2): warning: y\n0:9(5): error: syntax error\nmore"),
              "0:9(5): error: syntax error");
    EXPECT_EQ(firstErrorLine("cannot read export\nsecond"), "cannot read export");
}

namespace {

std::vector<std::uint8_t> frameOf(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    std::vector<std::uint8_t> rgba;
    for (int i = 0; i < w * h; ++i) rgba.insert(rgba.end(), {r, g, b, 255});
    return rgba;
}

void setPixel(std::vector<std::uint8_t>& rgba, int index, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    rgba[4 * index] = r, rgba[4 * index + 1] = g, rgba[4 * index + 2] = b;
}

}  // namespace

// The old rule ("not every pixel the same") passed both of these.
TEST(CompatFrameMeasure, OnePixelOrAFaintHazeIsNotAPicture) {
    const int w = 160, h = 90;
    std::vector<std::uint8_t> one = frameOf(w, h, 0, 0, 0);
    setPixel(one, 5 * w + 7, 255, 255, 255);
    const FrameShare single = measureFrame(one);
    EXPECT_EQ(single.dominant, (std::array<std::uint8_t, 3>{0, 0, 0}));
    EXPECT_NEAR(single.otherShare, 1.0 / (w * h), 1e-12);
    EXPECT_TRUE(nearlyUniform(single));

    // Mean 0.1/255: one pixel in ten at 1/255 (within the tolerance of black).
    std::vector<std::uint8_t> haze = frameOf(w, h, 0, 0, 0);
    for (int i = 0; i < w * h; i += 10) setPixel(haze, i, 1, 1, 1);
    const FrameShare faint = measureFrame(haze);
    EXPECT_NEAR(faint.meanLevel, 0.1, 1e-9);
    EXPECT_EQ(faint.otherShare, 0.0);
    EXPECT_TRUE(nearlyUniform(faint));
}

TEST(CompatFrameMeasure, ASparseButRealPictureIsNotDegenerate) {
    const int w = 160, h = 90;
    // A thin ring: about 2% of the pixels (the share the fixed-pixels test shader has at 320x180).
    std::vector<std::uint8_t> ring = frameOf(w, h, 0, 0, 0);
    int lit = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double d = std::hypot(x - 80.0, y - 45.0);
            if (std::abs(d - 30.0) < 0.6) setPixel(ring, y * w + x, 200, 40, 40), ++lit;
        }
    const FrameShare share = measureFrame(ring);
    EXPECT_NEAR(share.otherShare, static_cast<double>(lit) / (w * h), 1e-12);
    EXPECT_GT(share.otherShare, kMinOtherShare);
    EXPECT_FALSE(nearlyUniform(share));
    // Just below and just above the threshold.
    std::vector<std::uint8_t> few = frameOf(w, h, 10, 10, 10);
    const int needed = static_cast<int>(std::ceil(kMinOtherShare * w * h));
    for (int i = 0; i < needed - 1; ++i) setPixel(few, i, 10, 10, 13);
    EXPECT_TRUE(nearlyUniform(measureFrame(few)));
    setPixel(few, needed - 1, 10, 10, 13);
    EXPECT_FALSE(nearlyUniform(measureFrame(few)));
}

TEST(CompatFrameMeasure, AFlashIsADominantColourChangeBeyondTheTolerance) {
    EXPECT_FALSE(colourChanged({0, 0, 0}, {1, 2, 0}));  // dithering of black
    EXPECT_TRUE(colourChanged({0, 0, 0}, {0, 0, 3}));
    EXPECT_TRUE(colourChanged({255, 255, 255}, {0, 0, 0}));
}

namespace {
// Every key of the key script goes down once and up once, one at a time, each held for
// kKeyHoldFrames frames; probeKeyHeldAt says which one is down.
TEST(CompatProbeScript, TheKeyScriptHoldsEachKeyInTurnAndReleasesIt) {
    std::vector<int> down;
    int held = -1;
    for (int f = 0; f < toyhost::compat::probeKeyFrames() + 5; ++f) {
        for (const toyhost::InputEvent& e : toyhost::compat::probeKeysAt(f)) {
            if (e.type == toyhost::InputEvent::Type::KeyDown) {
                EXPECT_EQ(held, -1) << "a key goes down while another is held, frame " << f;
                held = e.key;
                down.push_back(e.key);
            } else {
                ASSERT_EQ(e.type, toyhost::InputEvent::Type::KeyUp);
                EXPECT_EQ(e.key, held) << "frame " << f;
                held = -1;
            }
        }
        const int index = toyhost::compat::probeKeyHeldAt(f);
        if (held == -1) EXPECT_EQ(index, -1) << "frame " << f;
        else EXPECT_EQ(toyhost::compat::kProbeKeys[index].code, held) << "frame " << f;
    }
    EXPECT_EQ(held, -1) << "the last key is released";
    ASSERT_EQ(static_cast<int>(down.size()), toyhost::compat::kProbeKeyCount);
    EXPECT_EQ(down.front(), 32) << "Space first";
}
}  // namespace
