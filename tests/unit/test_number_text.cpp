// Numbers as a user types them in an option (core/NumberText): decimal digits only, nothing around
// them, finite; and the watchdog limits' range (0 = off, else at least 0.1 s). The CLI's use of
// them (--frames '' and --frames 0x10 are usage errors) is in tests/reliability/test_catalogue.cpp.
#include <gtest/gtest.h>

#include <climits>

#include "core/NumberText.h"

using namespace toyhost;

TEST(NumberText, WholeNumbersAreDecimalDigitsOnly) {
    EXPECT_EQ(parseDecimalInteger("42"), 42);
    EXPECT_EQ(parseDecimalInteger("-3"), -3);
    EXPECT_EQ(parseDecimalInteger("010"), 10);  // decimal, not octal 8
    EXPECT_EQ(parseDecimalInteger("9223372036854775807"), LLONG_MAX);
    for (const char* bad : {"", "-", "+4", " 4", "4 ", "4.0", "0x10", "0X10", "0o17", "0b101", "1e3", "4a", "--4",
                            "9223372036854775808", "99999999999999999999"})
        EXPECT_FALSE(parseDecimalInteger(bad).has_value()) << '"' << bad << '"';
}

TEST(NumberText, DecimalNumbersAreFiniteAndWrittenInDecimal) {
    EXPECT_EQ(parseDecimalNumber("2"), 2.0);
    EXPECT_EQ(parseDecimalNumber("-0.5"), -0.5);
    EXPECT_EQ(parseDecimalNumber(".5"), 0.5);
    EXPECT_EQ(parseDecimalNumber("5."), 5.0);
    EXPECT_EQ(parseDecimalNumber("1e-3"), 1e-3);
    EXPECT_EQ(parseDecimalNumber("2.5E+2"), 250.0);
    EXPECT_EQ(parseDecimalNumber("1e-9"), 1e-9);
    for (const char* bad : {"", ".", "-", "e3", "1e", "1e+", "0x1p4", "0x10", "inf", "-inf", "nan", "infinity", "1e400",
                            "1,5", " 1", "1 ", "+1", "1.2.3", "30fps"})
        EXPECT_FALSE(parseDecimalNumber(bad).has_value()) << '"' << bad << '"';
}

TEST(NumberText, ProblemsSayWhatIsWrong) {
    EXPECT_EQ(wholeNumberProblem("12", INT_MIN, INT_MAX), "");
    EXPECT_EQ(wholeNumberProblem("", INT_MIN, INT_MAX), "expected a whole number, not an empty value");
    EXPECT_EQ(wholeNumberProblem("0x10", INT_MIN, INT_MAX), "expected a whole number in decimal digits, not \"0x10\"");
    EXPECT_EQ(wholeNumberProblem("99999999999", INT_MIN, INT_MAX), "\"99999999999\" is too large (at most 2147483647)");
    EXPECT_EQ(wholeNumberProblem("99999999999999999999", INT_MIN, INT_MAX),
              "\"99999999999999999999\" is too large (at most 2147483647)");
    EXPECT_EQ(wholeNumberProblem("-5", 0, 9), "\"-5\" is too small (at least 0)");
    EXPECT_EQ(decimalNumberProblem("0.25"), "");
    EXPECT_EQ(decimalNumberProblem(""), "expected a number, not an empty value");
    EXPECT_EQ(decimalNumberProblem("nan"), "expected a decimal number (like 2, 0.5 or 1e-3), not \"nan\"");
    EXPECT_EQ(decimalNumberProblem("1e400"), "\"1e400\" is beyond the range of numbers");
}

// A watchdog limit below 0.1 s measured the watchdog's own polling, and was reported as
// "0.0 s, longer than 0.0" (issue 16): it is refused, 0 still turns the limit off.
TEST(NumberText, TimeoutsAreOffOrAtLeastATenthOfASecond) {
    for (const char* good : {"0", "0.0", "0.1", "0.5", "60", "1e6"}) EXPECT_EQ(timeoutSecondsProblem(good), "") << good;
    EXPECT_EQ(timeoutSecondsProblem("1e-9"), "must be 0 (off) or from 0.1 to 1000000 seconds, not \"1e-9\"");
    EXPECT_EQ(timeoutSecondsProblem("0.05"), "must be 0 (off) or from 0.1 to 1000000 seconds, not \"0.05\"");
    EXPECT_EQ(timeoutSecondsProblem("-1"), "must be 0 (off) or from 0.1 to 1000000 seconds, not \"-1\"");
    EXPECT_EQ(timeoutSecondsProblem("2e6"), "must be 0 (off) or from 0.1 to 1000000 seconds, not \"2e6\"");
    EXPECT_EQ(timeoutSecondsProblem("nan"), "expected a decimal number (like 2, 0.5 or 1e-3), not \"nan\"");
}

// Sizes, frame ranges, shards and regions are whole numbers joined by a separator, each part read
// as one whole number: `--size 4294967396x100` once wrapped to 100x100 and `99999999999x1` was
// refused as "1215752191x1" (sscanf's %d), 010 was read as 10 or 8 depending on the parser.
TEST(NumberText, ListsOfWholeNumbersAreReadPartByPart) {
    const WholeNumbers size = wholeNumbersIn("800x450", "xX", 2, INT_MIN, INT_MAX);
    EXPECT_EQ(size.problem, "");
    EXPECT_EQ(size.values, (std::vector<long long>{800, 450}));
    EXPECT_EQ(wholeNumbersIn("16X8", "xX", 2, INT_MIN, INT_MAX).values, (std::vector<long long>{16, 8}));
    EXPECT_EQ(wholeNumbersIn("0,0,64,36", ",", 4, 0, INT_MAX).values, (std::vector<long long>{0, 0, 64, 36}));
    EXPECT_EQ(wholeNumbersIn("4294967396x100", "xX", 2, INT_MIN, INT_MAX).problem,
              "\"4294967396\" is too large (at most 2147483647)");
    EXPECT_EQ(wholeNumbersIn("99999999999x1", "xX", 2, INT_MIN, INT_MAX).problem,
              "\"99999999999\" is too large (at most 2147483647)");
    EXPECT_EQ(wholeNumbersIn("0x10:5", ":", 2, 0, INT_MAX).problem,
              "expected a whole number in decimal digits, not \"0x10\"");
    EXPECT_EQ(wholeNumbersIn("16x8x", "xX", 2, INT_MIN, INT_MAX).problem,
              "expected 2 whole numbers joined by 'x', not \"16x8x\"");
    EXPECT_EQ(wholeNumbersIn("16", "xX", 2, INT_MIN, INT_MAX).problem, "expected 2 whole numbers joined by 'x', not \"16\"");
    EXPECT_EQ(wholeNumbersIn("x8", "xX", 2, INT_MIN, INT_MAX).problem, "expected a whole number, not an empty value");
    EXPECT_EQ(wholeNumbersIn("-1/4", "/", 2, 0, INT_MAX).problem, "\"-1\" is too small (at least 0)");
    for (const char* bad : {" 16x8", "+16x8", "16 x8", "16x8 ", "1e3x8", "16.0x8"})
        EXPECT_NE(wholeNumbersIn(bad, "xX", 2, INT_MIN, INT_MAX).problem, "") << bad;
    EXPECT_TRUE(wholeNumbersIn("16x", "xX", 2, INT_MIN, INT_MAX).values.empty());
}
