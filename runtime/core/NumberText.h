// NumberText: numbers as a user writes them in a command-line option: decimal digits only (no 0x10,
// 0o17 or 0b101, which CLI11 and strtol-style parsers would take as 16, 15 and 5), nothing before
// or after them, finite. The CLI checks every numeric option with these before converting it, and
// library callers can use them for the same strings. No GL needed.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toyhost {

// "42", "-3": an optional '-' and decimal digits, within long long; nullopt for anything else
// ("", " 4", "+4", "4.0", "0x10", "1e3", "99999999999999999999").
std::optional<long long> parseDecimalInteger(std::string_view text);

// "2", "-0.5", ".5", "1e-3", "2.5E+2": an optional '-', decimal digits with an optional fraction
// and exponent, finite; nullopt for "", "0x1p4", "inf", "nan", "1e400", "1,5", " 1".
std::optional<double> parseDecimalNumber(std::string_view text);

// Why `text` is not a whole number between `min` and `max` (decimal digits only), in words for a
// usage message ("expected a whole number in decimal digits, not \"0x10\"", "\"99999999999\" is
// too large (at most 2147483647)"); "" when it is one.
std::string wholeNumberProblem(std::string_view text, long long min, long long max);

// `count` whole numbers joined by one of `separators`: "800x450" (sizes, "xX"), "0:100" (":"),
// "1/4" ("/"), "0,0,64,36" (","). Each part is read as wholeNumberProblem reads it (decimal digits
// only, within [min, max]: no wrap at 2^32, no 0x10, no 010 read as octal).
struct WholeNumbers {
    std::vector<long long> values;  // `count` of them when `problem` is empty
    std::string problem;            // why `text` is not such a list, in words; "" when it is
};
WholeNumbers wholeNumbersIn(std::string_view text, std::string_view separators, std::size_t count, long long min,
                            long long max);

// Why `text` is not a decimal number; "" when it is one.
std::string decimalNumberProblem(std::string_view text);

// Why `text` is not a usable watchdog limit in seconds: 0 (off) or from kMinTimeoutSeconds to
// kMaxTimeoutSeconds (core/Defaults.h); "" when it is one.
std::string timeoutSecondsProblem(std::string_view text);

}  // namespace toyhost
