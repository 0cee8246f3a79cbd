// FrameClock: the fixed time step (iTime, iTimeDelta) of headless runs, the iDate that goes with
// it, and parseWallClock.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "timing/FrameClock.h"

using namespace toyhost;

namespace {

double wallClock(const std::string& text) {
    Result<double> r = parseWallClock(text);
    EXPECT_TRUE(r.ok()) << text << ": " << (r.ok() ? "" : r.error().text());
    return r.ok() ? *r : 0.0;
}

void expectDate(const glm::vec4& d, float year, float month, float day, float seconds, const std::string& what) {
    EXPECT_EQ(d.x, year) << what << ": year";
    EXPECT_EQ(d.y, month) << what << ": month (0-based)";
    EXPECT_EQ(d.z, day) << what << ": day";
    EXPECT_FLOAT_EQ(d.w, seconds) << what << ": seconds since midnight";
}

}  // namespace

TEST(FrameClock, TimeIsStartPlusFrameOverFps) {
    const FrameClock c(60.0, 0.0, 0.0);
    EXPECT_EQ(c.fps(), 60.0);
    EXPECT_EQ(c.time(0), 0.0);
    EXPECT_DOUBLE_EQ(c.time(1), 1.0 / 60.0);
    EXPECT_DOUBLE_EQ(c.time(60), 1.0);
    EXPECT_DOUBLE_EQ(c.time(90), 1.5);
    EXPECT_DOUBLE_EQ(c.timeDelta(), 1.0 / 60.0);

    const FrameClock shifted(30.0, 12.5, 0.0);
    EXPECT_EQ(shifted.time(0), 12.5);
    EXPECT_DOUBLE_EQ(shifted.time(3), 12.6);
    EXPECT_DOUBLE_EQ(shifted.time(30), 13.5);
    EXPECT_DOUBLE_EQ(shifted.timeDelta(), 1.0 / 30.0);

    const FrameClock slow(1.0, 0.0, 0.0);
    EXPECT_EQ(slow.time(5), 5.0);
    EXPECT_EQ(slow.timeDelta(), 1.0);
    // Computed from the frame number, not accumulated: no drift after many frames.
    EXPECT_DOUBLE_EQ(FrameClock(60.0, 0.0, 0.0).time(60 * 3600), 3600.0);
}

TEST(FrameClock, ParseWallClockForms) {
    EXPECT_EQ(wallClock("1970-01-01"), 0.0);
    EXPECT_EQ(wallClock("1970-01-01T00:00:00"), 0.0);
    EXPECT_EQ(wallClock("1970-01-02T01:02:03"), 86400.0 + 3723.0);
    EXPECT_EQ(wallClock("1970-01-02 01:02:03"), 86400.0 + 3723.0);
    EXPECT_EQ(wallClock("2024-02-29T23:59:59.5"), 1709251199.5);
    EXPECT_EQ(wallClock("2000-01-01"), 946684800.0);
    EXPECT_EQ(wallClock("2016-12-31T23:59:60"), wallClock("2017-01-01"));  // a leap second
}

TEST(FrameClock, WallClockTextReadsBack) {
    EXPECT_EQ(wallClockText(wallClock("2024-02-29T23:59:59.5")), "2024-02-29T23:59:59.500000");
    EXPECT_EQ(wallClockText(0.0), "1970-01-01T00:00:00.000000");
    for (double t : {0.25, 946684800.0, 1709251199.999, 4102444800.123456}) EXPECT_NEAR(wallClock(wallClockText(t)), t, 1e-6);
}

TEST(FrameClock, DateFieldsForAFixedWallClock) {
    const FrameClock c(1.0, 0.0, wallClock("2024-02-29T23:59:59.5"));
    expectDate(c.date(0), 2024, 1, 29, 86399.5, "frame 0");  // February is month 1
    // One frame later at 1 fps: past midnight, into March 1.
    expectDate(c.date(1), 2024, 2, 1, 0.5, "frame 1");
    expectDate(c.date(3601), 2024, 2, 1, 3600.5, "frame 3601");
}

TEST(FrameClock, DateIsIndependentOfStartTime) {
    // iTime's offset does not move the wall clock: frame 0 is the wall-clock start.
    const FrameClock c(10.0, 100.0, wallClock("2023-06-15T12:00:00"));
    expectDate(c.date(0), 2023, 5, 15, 43200.0, "frame 0");
    expectDate(c.date(25), 2023, 5, 15, 43202.5, "frame 25");
}

TEST(FrameClock, MonthIsZeroBasedAndYearRollsOver) {
    expectDate(FrameClock(60.0, 0.0, wallClock("2023-01-01")).date(0), 2023, 0, 1, 0.0, "January");
    expectDate(FrameClock(60.0, 0.0, wallClock("2023-12-31T23:59:59")).date(0), 2023, 11, 31, 86399.0, "December");
    expectDate(FrameClock(2.0, 0.0, wallClock("2023-12-31T23:59:59")).date(3), 2024, 0, 1, 0.5, "New Year");
}

TEST(FrameClock, ParseWallClockErrors) {
    for (const char* bad : {"", "now", "2024", "2024-02", "2024/02/29", "2024-00-10", "2024-13-01", "2024-01-00",
                            "2024-01-32", "2024-02-29T24:00:00", "2024-02-29T12:60:00", "2024-02-29T12:00:61",
                            "2024-02-29T12:00:-1", "2024-02-29T12:30", "2024-02-29T12", "2024-02-29X12:00:00",
                            "2024-02-29T12:00:00Z", "2024-02-29T12:00:00 junk", "2024-02-29 ", "2024-02-29T12:00:nan",
                            // Days that do not exist in their month.
                            "2023-02-29", "2024-02-30", "2024-04-31T00:00:00", "2100-02-29"}) {
        Result<double> r = parseWallClock(bad);
        ASSERT_FALSE(r.ok()) << "\"" << bad << "\" was accepted as " << std::to_string(*r);
        EXPECT_EQ(r.error().first().message, "date \"" + std::string(bad) + "\" is not YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS");
    }
}

TEST(FrameClock, LocalWallClockNowIsPlausible) {
    // After 2020-01-01 and before 2200-01-01, whatever the time zone.
    const double now = localWallClockNow();
    EXPECT_GT(now, wallClock("2020-01-01"));
    EXPECT_LT(now, wallClock("2200-01-01"));
    EXPECT_FALSE(std::isnan(now));
}
