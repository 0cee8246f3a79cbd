// The sample pattern of supersampling and motion blur (timing/SamplePattern.h): the offsets are a
// regular grid centred in the pixel, the times the midpoints of equal parts of the shutter
// interval, every pair once; a sample's clock moves iTime and iDate (by the wall clock, across
// midnight too) and keeps the frame's step. No GL (the checks of the values: tests/gl/test_sampling.cpp).
#include <gtest/gtest.h>

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

TEST(SamplePattern, MotionTimesAreMidpointsOfTheShutterIntervalAndEveryPairIsDrawn) {
    SamplingDesc d;
    d.supersample = 2;
    d.motionBlur = 4;
    d.shutterDegrees = 180;
    const std::vector<SamplePoint> points = samplePattern(d);
    ASSERT_EQ(points.size(), 16u);
    EXPECT_EQ(samplesPerFrame(d), 16);
    // Time-major: four offsets at each of 1/16, 3/16, 5/16, 7/16 of the step (half of it open).
    for (int k = 0; k < 4; ++k)
        for (int s = 0; s < 4; ++s) {
            EXPECT_DOUBLE_EQ(points[static_cast<std::size_t>(k * 4 + s)].fraction, (k + 0.5) / 4 * 0.5);
            EXPECT_EQ(points[static_cast<std::size_t>(k * 4 + s)].offset, points[static_cast<std::size_t>(s)].offset);
        }
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
