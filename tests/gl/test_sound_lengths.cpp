// The Sound pass's length is a number checked at every boundary (issue 31): the library's
// renderSound refuses a negative, NaN, infinite or over-an-hour length naming `seconds` (before,
// -1 and NaN gave 180 s, infinity rendered without end and 1e7 let bad_alloc escape the API), 0
// keeps meaning the site's 180 s; `toyhost sound --seconds 0` is refused (it rendered 180 s).
#include "GlTestSupport.h"

#include <cmath>
#include <limits>

#include <toyhost/Session.h>

namespace toyhost::testing {
namespace {

TEST(SoundLengths, ImpossibleLengthsAreRefusedNamingSeconds) {
    Result<Shadertoy> cube = Shadertoy::load(sourceDir() / "shadertoys/cube-probe");
    ASSERT_TRUE(cube.ok()) << cube.error().text();
    runOnGlThread([&] {
        SessionSettings settings;
        settings.width = 16;
        settings.height = 16;
        Result<std::unique_ptr<Session>> session = Session::createHeadless(*cube, settings);
        ASSERT_TRUE(session.ok()) << session.error().text();
        for (double seconds : {-1.0, std::nan(""), std::numeric_limits<double>::infinity(), 1e7, 3600.5}) {
            Result<std::vector<float>> sound = (*session)->renderSound(seconds);
            ASSERT_FALSE(sound.ok()) << seconds;
            EXPECT_EQ(sound.error().first().field, "seconds") << seconds;
            EXPECT_EQ(sound.error().first().code, Code::Usage) << seconds;
        }
        Result<std::vector<float>> half = (*session)->renderSound(0.5);
        ASSERT_TRUE(half.ok()) << half.error().text();
        EXPECT_EQ(half->size(), static_cast<std::size_t>(2 * 22050));
    });
    const CommandResult zero = runToyhost("sound " + (sourceDir() / "shadertoys/cube-probe").string() +
                                          " --seconds 0 --out " + (testOutputDir() / "zero.wav").string());
    EXPECT_EQ(zero.exitCode, 2) << zero.output;
    EXPECT_NE(zero.output.find("--seconds"), std::string::npos) << zero.output;
    EXPECT_FALSE(std::filesystem::exists(testOutputDir() / "zero.wav"));
}

}  // namespace
}  // namespace toyhost::testing
