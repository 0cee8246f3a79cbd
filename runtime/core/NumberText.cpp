#include "core/NumberText.h"

#include <charconv>
#include <cmath>

#include "core/Defaults.h"

namespace toyhost {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The shape of a decimal number: [-] digits [. digits] [e|E [+|-] digits], with at least one digit
// before the exponent. from_chars alone would also take "inf", "nan" and (with another format) hex.
bool looksDecimal(std::string_view text) {
    std::size_t i = 0;
    if (i < text.size() && text[i] == '-') ++i;
    std::size_t digits = 0;
    while (i < text.size() && isDigit(text[i])) ++i, ++digits;
    if (i < text.size() && text[i] == '.') {
        ++i;
        while (i < text.size() && isDigit(text[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        ++i;
        if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
        std::size_t exponentDigits = 0;
        while (i < text.size() && isDigit(text[i])) ++i, ++exponentDigits;
        if (exponentDigits == 0) return false;
    }
    return i == text.size();
}

// Appended in order: `"\"" + std::string(...)` inserts at 0, where GCC 12 warns a false -Wrestrict
// (GCC bug 105651).
std::string shown(std::string_view text) {
    std::string quoted;
    quoted.reserve(text.size() + 2);
    quoted += '"';
    quoted += text;
    quoted += '"';
    return quoted;
}

// "0.1" and "1000000" rather than "0.100000" and "1e+06".
std::string trimmed(double value) {
    if (value == std::floor(value) && std::abs(value) < 1e15) return std::to_string(static_cast<long long>(value));
    char text[32];
    const auto [end, ec] = std::to_chars(text, text + sizeof text, value);
    return ec == std::errc() ? std::string(text, end) : std::to_string(value);
}

}  // namespace

std::optional<long long> parseDecimalInteger(std::string_view text) {
    std::size_t i = text.size() > 0 && text[0] == '-' ? 1 : 0;
    if (i == text.size()) return std::nullopt;
    for (std::size_t j = i; j < text.size(); ++j)
        if (!isDigit(text[j])) return std::nullopt;
    long long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, 10);
    if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
    return value;
}

std::optional<double> parseDecimalNumber(std::string_view text) {
    if (!looksDecimal(text)) return std::nullopt;
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::string wholeNumberProblem(std::string_view text, long long min, long long max) {
    if (text.empty()) return "expected a whole number, not an empty value";
    bool digitsOnly = true;
    for (std::size_t i = text[0] == '-' ? 1 : 0; i < text.size(); ++i) digitsOnly = digitsOnly && isDigit(text[i]);
    if (!digitsOnly || text == "-") return "expected a whole number in decimal digits, not " + shown(text);
    const std::optional<long long> value = parseDecimalInteger(text);
    if (!value || *value > max) return shown(text) + " is too large (at most " + std::to_string(max) + ")";
    if (*value < min) return shown(text) + " is too small (at least " + std::to_string(min) + ")";
    return "";
}

WholeNumbers wholeNumbersIn(std::string_view text, std::string_view separators, std::size_t count, long long min,
                            long long max) {
    WholeNumbers out;
    std::size_t start = 0;
    for (std::size_t part = 0; part < count; ++part) {
        std::size_t end = part + 1 == count ? text.size() : text.find_first_of(separators, start);
        if (end == std::string_view::npos) {
            out.problem = "expected " + std::to_string(count) + " whole numbers joined by '" +
                          std::string(1, separators.front()) + "', not " + shown(text);
            break;
        }
        const std::string_view piece = text.substr(start, end - start);
        if (piece.find_first_of(separators) != std::string_view::npos) {
            out.problem = "expected " + std::to_string(count) + " whole numbers joined by '" +
                          std::string(1, separators.front()) + "', not " + shown(text);
            break;
        }
        if (std::string problem = wholeNumberProblem(piece, min, max); !problem.empty()) {
            out.problem = std::move(problem);
            break;
        }
        out.values.push_back(*parseDecimalInteger(piece));
        start = end + 1;
    }
    if (!out.problem.empty()) out.values.clear();
    return out;
}

std::string decimalNumberProblem(std::string_view text) {
    if (text.empty()) return "expected a number, not an empty value";
    if (!looksDecimal(text)) return "expected a decimal number (like 2, 0.5 or 1e-3), not " + shown(text);
    if (!parseDecimalNumber(text)) return shown(text) + " is beyond the range of numbers";
    return "";
}

std::string timeoutSecondsProblem(std::string_view text) {
    if (std::string problem = decimalNumberProblem(text); !problem.empty()) return problem;
    const double seconds = *parseDecimalNumber(text);
    if (seconds == 0) return "";
    if (seconds < defaults::kMinTimeoutSeconds || seconds > defaults::kMaxTimeoutSeconds)
        return "must be 0 (off) or from " + trimmed(defaults::kMinTimeoutSeconds) + " to " +
               trimmed(defaults::kMaxTimeoutSeconds) + " seconds, not " + shown(text);
    return "";
}

}  // namespace toyhost
