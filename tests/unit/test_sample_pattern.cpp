// The sample pattern of supersampling and motion blur (timing/SamplePattern.h): the offsets are a
// regular grid centred in the pixel, the times the midpoints of equal strata of the shutter
// interval, one for each draw (stratified), placed by the shutter offset; a sample's clock moves iTime and iDate (by the wall clock, across
// midnight too) and keeps the frame's step. No GL (the checks of the values: tests/gl/test_sampling.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <utility>

#include "timing/FrameClock.h"
#include "timing/SamplePattern.h"
#include "timing/Timeline.h"

using namespace toyhost;

TEST(SamplePattern, TheDefaultIsOneDrawAtThePixelCentreAndTheFramesTime) {
    const SamplingDesc site;
    EXPECT_TRUE(isSingleSample(site));
    const std::vector<SamplePoint> points = samplePattern(site);
    ASSERT_EQ(points.size(), 1u);
    EXPECT_EQ(points[0].offset, glm::vec2(0.0f));
    EXPECT_EQ(points[0].fraction, 0.0);
    // A shutter alone changes nothing: one time is the frame's.
    SamplingDesc wide;
    wide.shutterDegrees = 360;
    EXPECT_EQ(samplePattern(wide)[0].fraction, 0.0);
}

TEST(SamplePattern, SupersampleOffsetsAreARegularGridCentredInThePixel) {
    SamplingDesc d;
    d.supersample = 4;
    const std::vector<SamplePoint> points = samplePattern(d);
    ASSERT_EQ(points.size(), 16u);
    std::set<std::pair<float, float>> seen;
    glm::vec2 sum(0.0f);
    for (const SamplePoint& p : points) {
        seen.insert({p.offset.x, p.offset.y});
        sum += p.offset;
        EXPECT_EQ(p.fraction, 0.0);
    }
    EXPECT_EQ(seen.size(), 16u);
    EXPECT_EQ(sum, glm::vec2(0.0f));  // centred: the average position is the pixel centre
    EXPECT_EQ(points[0].offset, glm::vec2(-0.375f, -0.375f));
    EXPECT_EQ(points[1].offset, glm::vec2(-0.125f, -0.375f));  // columns first
    EXPECT_EQ(points[15].offset, glm::vec2(0.375f, 0.375f));
}

TEST(SamplePattern, MotionTimesAloneAreMidpointsOfEqualPartsOfTheShutterInterval) {
    SamplingDesc d;
    d.motionBlur = 4;
    d.shutterDegrees = 180;
    const std::vector<SamplePoint> points = samplePattern(d);
    ASSERT_EQ(points.size(), 4u);
    for (int k = 0; k < 4; ++k) {  // 1/16, 3/16, 5/16, 7/16 of the step (half of it open)
        EXPECT_DOUBLE_EQ(points[static_cast<std::size_t>(k)].fraction, (k + 0.5) / 4 * 0.5);
        EXPECT_EQ(points[static_cast<std::size_t>(k)].offset, glm::vec2(0.0f));
    }
}

// Issue 44: with both, every draw has a time of its own (N x N x S strata of the shutter), so that
// the same draws make a continuous streak instead of S copies; each offset gets one stratum in
// each of S equal parts (its own times spread over the whole interval), and the pattern is fixed.
TEST(SamplePattern, WithSupersamplingEveryDrawHasAStratumOfTheShutterOfItsOwn) {
    SamplingDesc d;
    d.supersample = 2;
    d.motionBlur = 4;
    d.shutterDegrees = 180;
    const std::vector<SamplePoint> points = samplePattern(d);
    ASSERT_EQ(points.size(), 16u);
    EXPECT_EQ(samplesPerFrame(d), 16);
    std::set<int> strata;
    for (int k = 0; k < 4; ++k)
        for (int o = 0; o < 4; ++o) {
            const SamplePoint& p = points[static_cast<std::size_t>(k * 4 + o)];
            // Part-major: the same four offsets in each part, in the same order.
            EXPECT_EQ(p.offset, points[static_cast<std::size_t>(o)].offset);
            const double stratum = p.fraction / 0.5 * 16 - 0.5;  // midpoints of 16 strata
            EXPECT_NEAR(stratum, std::round(stratum), 1e-9);
            EXPECT_EQ(static_cast<int>(std::round(stratum)) / 4, k) << "offset " << o << " leaves part " << k;
            strata.insert(static_cast<int>(std::round(stratum)));
        }
    EXPECT_EQ(strata.size(), 16u);
    EXPECT_EQ(*strata.begin(), 0);
    EXPECT_EQ(*strata.rbegin(), 15);
    // Not the same sub-stratum order in every part (the offsets are shuffled per part).
    bool shuffled = false;
    for (int k = 1; k < 4; ++k)
        for (int o = 0; o < 4; ++o)
            shuffled |= std::round(points[static_cast<std::size_t>(k * 4 + o)].fraction * 32 - 0.5) - k * 4 !=
                        std::round(points[static_cast<std::size_t>(o)].fraction * 32 - 0.5);
    EXPECT_TRUE(shuffled);
    // Deterministic: the same every time.
    const std::vector<SamplePoint> again = samplePattern(d);
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(points[i].fraction, again[i].fraction);
    // Supersampling alone stays at the frame's time.
    d.motionBlur = 1;
    for (const SamplePoint& p : samplePattern(d)) EXPECT_EQ(p.fraction, 0.0);
}

TEST(SamplePattern, TheShutterOffsetPlacesTheIntervalAgainstTheFramesTime) {
    SamplingDesc d;
    d.supersample = 4;
    d.motionBlur = 8;
    d.shutterDegrees = 180;
    auto range = [&](ShutterOffset offset) {
        d.shutterOffset = offset;
        double low = 1, high = -1, sum = 0;
        for (const SamplePoint& p : samplePattern(d)) {
            low = std::min(low, p.fraction);
            high = std::max(high, p.fraction);
            sum += p.fraction;
        }
        return std::array<double, 3>{low, high, sum / samplesPerFrame(d)};
    };
    const double half = 0.5 / 128 / 2;  // half a stratum
    const std::array<double, 3> open = range(ShutterOffset::Open);
    EXPECT_DOUBLE_EQ(open[0], half);
    EXPECT_DOUBLE_EQ(open[1], 0.5 - half);
    EXPECT_NEAR(open[2], 0.25, 1e-12);  // the interval's middle
    const std::array<double, 3> centre = range(ShutterOffset::Centre);
    EXPECT_DOUBLE_EQ(centre[0], -0.25 + half);
    EXPECT_NEAR(centre[2], 0.0, 1e-12);
    const std::array<double, 3> close = range(ShutterOffset::Close);
    EXPECT_DOUBLE_EQ(close[1], -half);
    EXPECT_NEAR(close[2], -0.25, 1e-12);
    EXPECT_EQ(parseShutterOffset("center"), ShutterOffset::Centre);
    EXPECT_EQ(parseShutterOffset("middle"), std::nullopt);
    EXPECT_EQ(parseSampleSpaceLinear("display"), false);
    EXPECT_EQ(parseSampleSpaceLinear("gamma"), std::nullopt);
}

TEST(SamplePattern, ASubFrameMovesITimeAndIDateAndKeepsTheStep) {
    TimelineDesc desc;
    desc.fps = 4;
    desc.startTime = 10;
    desc.wallClockStart = *parseWallClock("2024-02-29T23:59:59.625");
    const Timeline timeline(desc);
    const FrameTime frame = timeline.at(1);  // iTime 10.25, 23:59:59.875
    const FrameTime half = subFrameTime(frame, 0.5);
    EXPECT_DOUBLE_EQ(half.time, 10.375);
    EXPECT_DOUBLE_EQ(half.timeDelta, 0.25);
    EXPECT_DOUBLE_EQ(half.frameRate, 4);
    // 0.125 s later is past midnight: 1 March (month 2), 0.0 s.
    EXPECT_EQ(half.date, glm::vec4(2024, 2, 1, 0.0f));
    // The timeline's own sub-frame times agree.
    EXPECT_DOUBLE_EQ(timeline.at(1, 0.5).time, half.time);
    EXPECT_EQ(timeline.at(1, 0.5).date, half.date);
    EXPECT_EQ(subFrameTime(frame, 0).time, frame.time);
    // Without a wall clock (a caller's own time) iDate's seconds move with iTime.
    FrameTime own{5.0, 0.1, 10.0, glm::vec4(2024, 0, 1, 100.0f)};
    EXPECT_FLOAT_EQ(subFrameTime(own, 0.5).date.w, 100.05f);
}
