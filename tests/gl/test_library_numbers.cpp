// Numbers a caller hands the library's Session per frame are checked as the CLI checks its own
// (issue 31): a NaN or infinite iTime, a negative time delta, a negative frame rate, mouse
// coordinates that are NaN or beyond +-1e6 pixels (Python turns 1e40 into an infinite float), a keyCode outside 0..255 are refused naming
// the parameter, and nothing renders (iFrame stays); good values still render.
#include "GlTestSupport.h"

#include <cmath>
#include <limits>

#include <toyhost/Compare.h>
#include <toyhost/Session.h>

#include <functional>
#include <new>
#include <stdexcept>

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

// The property every numeric parameter of the public API has: NaN, +-infinity, 0 where it cannot be
// meant, negative, huge and beyond-int values are an error (never accepted with a silent default,
// never a crash or a hang). One row per parameter; a parameter added to the API gets a row here.
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kIntMax = std::numeric_limits<int>::max();
constexpr int kIntMin = std::numeric_limits<int>::min();

struct BadSetting {
    std::string name;
    std::function<void(SessionSettings&)> set;
};

TEST(LibraryNumbers, EverySessionSettingRefusesImpossibleValues) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/bench-trivial");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    std::vector<BadSetting> cases;
    for (int v : {0, -1, kIntMin, kIntMax, 1 << 20}) {
        cases.push_back({"width " + std::to_string(v), [v](SessionSettings& s) { s.width = v, s.height = 8; }});
        cases.push_back({"height " + std::to_string(v), [v](SessionSettings& s) { s.width = 8, s.height = v; }});
    }
    for (double v : {kNan, kInf, -kInf, 0.0, -5.0, 1e300})
        cases.push_back({"fps " + std::to_string(v), [v](SessionSettings& s) { s.fps = v; }});
    for (double v : {kNan, kInf, -kInf, 1e300, -1e300})
        cases.push_back({"startTime " + std::to_string(v), [v](SessionSettings& s) { s.startTime = v; }});
    for (double v : {kNan, kInf, -kInf, -1.0, 1e300}) {
        cases.push_back({"frameTimeout " + std::to_string(v), [v](SessionSettings& s) { s.frameTimeout = v; }});
        cases.push_back({"compileTimeout " + std::to_string(v), [v](SessionSettings& s) { s.compileTimeout = v; }});
        cases.push_back({"shutterDegrees " + std::to_string(v), [v](SessionSettings& s) { s.shutterDegrees = v; }});
    }
    for (int v : {0, -1, kIntMin, kIntMax}) {
        cases.push_back({"supersample " + std::to_string(v), [v](SessionSettings& s) { s.supersample = v; }});
        cases.push_back({"motionBlur " + std::to_string(v), [v](SessionSettings& s) { s.motionBlur = v; }});
    }
    cases.push_back({"date empty", [](SessionSettings& s) { s.date = ""; }});
    cases.push_back({"date nonsense", [](SessionSettings& s) { s.date = "2026-13-45T99:99:99"; }});
    runOnGlThread([&] {
        for (const BadSetting& c : cases) {
            SessionSettings settings;
            settings.width = 16;
            settings.height = 8;
            c.set(settings);
            Result<std::unique_ptr<Session>> made = Session::createHeadless(*probe, settings);
            EXPECT_FALSE(made.ok()) << c.name << " was accepted";
            if (!made.ok()) EXPECT_FALSE(made.error().first().message.empty()) << c.name;
        }
    });
}

TEST(LibraryNumbers, EverySessionCallRefusesImpossibleNumbers) {
    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/cube-probe");  // has a Sound pass
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    runOnGlThread([&] {
        SessionSettings settings;
        settings.width = 16;
        settings.height = 8;
        Result<std::unique_ptr<Session>> made = Session::createHeadless(*probe, settings);
        ASSERT_TRUE(made.ok()) << made.error().text();
        Session& s = **made;
        for (double v : {kNan, kInf, -kInf}) EXPECT_FALSE(s.stepAt(v, 0.1, 10).ok()) << "time " << v;
        for (double v : {kNan, kInf, -1.0}) EXPECT_FALSE(s.stepAt(1, v, 10).ok()) << "timeDelta " << v;
        for (double v : {kNan, kInf, -1.0}) EXPECT_FALSE(s.stepAt(1, 0.1, v).ok()) << "frameRate " << v;
        for (float v : {std::nanf(""), std::numeric_limits<float>::infinity(), -2e6f, 2e6f}) {
            for (const InputEvent& e : {InputEvent::mouseDown(v, 1), InputEvent::mouseDown(1, v),
                                        InputEvent::mouseMove(v, 1), InputEvent::mouseMove(1, v)})
                EXPECT_FALSE(s.step(std::span(&e, 1)).ok()) << "mouse " << v;
        }
        for (int v : {-1, 256, kIntMax, kIntMin}) {
            for (const InputEvent& e : {InputEvent::keyDown(v), InputEvent::keyUp(v)})
                EXPECT_FALSE(s.step(std::span(&e, 1)).ok()) << "key " << v;
        }
        EXPECT_EQ(s.frame(), 0) << "nothing rendered";
        for (int v : {0, -1, kIntMin, kIntMax, 1 << 20}) {
            EXPECT_FALSE(s.resize(v, 8).ok()) << "resize width " << v;
            EXPECT_FALSE(s.resize(8, v).ok()) << "resize height " << v;
        }
        EXPECT_EQ(s.width(), 16);
        for (double v : {kNan, kInf, -kInf, -1.0, 1e7, 1e300})
            EXPECT_FALSE(s.renderSound(v).ok()) << "renderSound " << v;
        auto none = [](const Session::RenderedFrame&) { return true; };
        for (auto [frames, every] : {std::pair{-1, 1}, {kIntMin, 1}, {1, 0}, {1, -1}, {1, kIntMin}}) {
            Session::RenderRequest request;
            request.frames = frames;
            request.every = every;
            EXPECT_FALSE(s.render(request, none).ok()) << "render frames " << frames << " every " << every;
        }
        EXPECT_EQ(s.frame(), 0) << "nothing rendered";
    });
}

TEST(LibraryNumbers, CompareRefusesImpossibleTolerancesAndGains) {
    const std::vector<std::uint8_t> a(4 * 4 * 4, 10), b(4 * 4 * 4, 12);
    for (double v : {kNan, 0.0, -1.0, -kInf}) {
        CompareTolerance t;
        t.minPsnr = v;
        Result<FrameDifference> d = compareImages(a, b, 4, 4, 3, t);
        EXPECT_FALSE(d.ok()) << "minPsnr " << v;
        if (!d.ok()) EXPECT_EQ(d.error().first().field, "min_psnr");
    }
    for (int v : {-1, 256, kIntMax, kIntMin}) {
        CompareTolerance t;
        t.maxDiff = v;
        EXPECT_FALSE(compareImages(a, b, 4, 4, 3, t).ok()) << "maxDiff " << v;
        EXPECT_FALSE(compareImages(a, b, 4, 4, 3, {}, nullptr, v).ok()) << "diffGain " << v;
    }
    for (int v : {-1, kIntMin}) {
        EXPECT_FALSE(compareImages(a, b, v, 4, 3).ok()) << "width " << v;
        EXPECT_FALSE(compareImages(a, b, 4, v, 3).ok()) << "height " << v;
    }
    for (int v : {0, 1, 2, 5, -1, kIntMax}) EXPECT_FALSE(compareImages(a, b, 4, 4, v).ok()) << "channels " << v;
    CompareTolerance infinite;
    infinite.minPsnr = kInf;  // identical only: a tolerance, not an error
    ASSERT_TRUE(compareImages(a, b, 4, 4, 3, infinite).ok());

    Result<Shadertoy> probe = Shadertoy::load(sourceDir() / "shadertoys/bench-trivial");
    ASSERT_TRUE(probe.ok()) << probe.error().text();
    runOnGlThread([&] {
        auto refused = [&](const std::function<void(CompareSettings&)>& set) {
            CompareSettings settings;
            settings.session.width = 16;
            settings.session.height = 8;
            settings.frames = 1;
            set(settings);
            return !compareShadertoys(*probe, *probe, settings).ok();
        };
        EXPECT_TRUE(refused([](CompareSettings& c) { c.frames = -1; }));
        EXPECT_TRUE(refused([](CompareSettings& c) { c.tolerance.minPsnr = kNan; }));
        EXPECT_TRUE(refused([](CompareSettings& c) { c.tolerance.maxDiff = 300; }));
        EXPECT_TRUE(refused([](CompareSettings& c) { c.diffGain = -1; }));
        EXPECT_TRUE(refused([](CompareSettings& c) { c.session.fps = kNan; }));
        EXPECT_TRUE(refused([](CompareSettings& c) {
            c.input = [](int, double) { return std::vector<InputEvent>{InputEvent::mouseDown(std::nanf(""), 0)}; };
        }));
        EXPECT_FALSE(refused([](CompareSettings&) {}));
    });
}

// An exception thrown on the GL thread (an allocation that failed) reaches the caller of
// runOnGlThread, where it can become an error, instead of ending the process from that thread.
TEST(LibraryNumbers, AnExceptionOnTheGlThreadReachesItsCaller) {
    EXPECT_THROW(runOnGlThread([] { throw std::bad_alloc(); }), std::bad_alloc);
    EXPECT_THROW(runOnGlThread([] { throw std::runtime_error("x"); }), std::runtime_error);
    int ran = 0;
    runOnGlThread([&] { ++ran; });
    EXPECT_EQ(ran, 1);
}

}  // namespace
}  // namespace toyhost::testing
