// Numbers a caller hands the library's Session per frame are checked as the CLI checks its own
// (issue 31): a NaN or infinite iTime, a negative time delta, a negative frame rate, mouse
// coordinates that are NaN or beyond +-1e6 pixels (Python turns 1e40 into an infinite float), a keyCode outside 0..255 are refused naming
// the parameter, and nothing renders (iFrame stays); good values still render.
#include "GlTestSupport.h"

#include <cmath>
#include <limits>

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

TEST(LibraryNumbers, StepAndStepAtRefuseImpossibleNumbersNamingThem) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/uniform-probe");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    runOnGlThread([&] {
        SessionSettings settings;
        settings.width = 16;
        settings.height = 16;
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*probe, settings);
        ASSERT_TRUE(made.ok()) << made.error().text();
        Session& s = **made;
        const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
        auto field = [](const Status& status) { return status ? std::string("(accepted)") : status.error().first().field; };
        EXPECT_EQ(field(s.stepAt(nan, 0.1, 10)), "time");
        EXPECT_EQ(field(s.stepAt(inf, 0.1, 10)), "time");
        EXPECT_EQ(field(s.stepAt(1.0, nan, 10)), "time_delta");
        EXPECT_EQ(field(s.stepAt(1.0, -1, 10)), "time_delta");
        EXPECT_EQ(field(s.stepAt(1.0, 0.1, -1)), "frame_rate");
        const InputEvent nanMouse = InputEvent::mouseDown(std::nanf(""), 3);
        const InputEvent farMouse = InputEvent::mouseMove(2e6f, 5);  // beyond +-1e6 pixels
        const InputEvent badKey = InputEvent::keyDown(300);
        EXPECT_EQ(field(s.step(std::span(&nanMouse, 1))), "mouse");
        EXPECT_EQ(field(s.step(std::span(&farMouse, 1))), "mouse");
        EXPECT_EQ(field(s.step(std::span(&badKey, 1))), "key");
        EXPECT_EQ(field(s.stepAt(1.0, 0.1, 10, std::span(&badKey, 1))), "key");
        EXPECT_EQ(s.frame(), 0) << "nothing rendered";
        const InputEvent good = InputEvent::mouseDown(3, 4);
        EXPECT_TRUE(s.step(std::span(&good, 1)).ok());
        EXPECT_TRUE(s.stepAt(2.0, 0.5, 0).ok());
        EXPECT_EQ(s.frame(), 2);
    });
}

}  // namespace
}  // namespace toyhost::testing
