// The compatibility runner's pure parts (tools/compat/ProbeScript.h): the visitor's mouse never
// crosses the exact centre and is released before the last frame, which is judged after the
// release; a failure shows its first error line, not the warnings before it.
#include <gtest/gtest.h>

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
