#include "timing/FrameClock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace toyhost {

FrameClock::FrameClock(double fps, double startTime, double wallClockStart)
    : fps_(fps), startTime_(startTime), wallClockStart_(wallClockStart) {}

glm::vec4 FrameClock::date(int frame) const { return dateOfTime(wallClockStart_, startTime_, time(frame)); }

glm::vec4 dateOfTime(double wallClockStart, double startTime, double time) {
    return dateAt(wallClockStart + (time - startTime));
}

glm::vec4 dateAt(double now) {
    const double whole = std::floor(now);
    std::time_t seconds = static_cast<std::time_t>(whole);
    std::tm fields{};
    gmtime_r(&seconds, &fields);
    const double sinceMidnight = fields.tm_hour * 3600.0 + fields.tm_min * 60.0 + fields.tm_sec + (now - whole);
    return {float(fields.tm_year + 1900), float(fields.tm_mon), float(fields.tm_mday), float(sinceMidnight)};
}

double localWallClockNow() {
    using namespace std::chrono;
    const double utc = duration<double>(system_clock::now().time_since_epoch()).count();
    std::time_t t = static_cast<std::time_t>(utc);
    std::tm local{};
    localtime_r(&t, &local);
    return utc + static_cast<double>(local.tm_gmtoff);
}

std::string wallClockText(double wallClock) {
    const double whole = std::floor(wallClock / 60.0) * 60.0;
    std::time_t minute = static_cast<std::time_t>(whole);
    std::tm fields{};
    gmtime_r(&minute, &fields);
    char text[64];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%09.6f", fields.tm_year + 1900, fields.tm_mon + 1,
                  fields.tm_mday, fields.tm_hour, fields.tm_min, std::min(wallClock - whole, 59.999999));
    return text;
}

Result<double> parseWallClock(const std::string& text) {
    int year, month, day, hour = 0, minute = 0;
    double second = 0;
    char sep = 'T';
    int dateEnd = -1, fullEnd = -1;  // characters consumed, to reject trailing text
    const int n = std::sscanf(text.c_str(), "%d-%d-%d%n%c%d:%d:%lf%n", &year, &month, &day, &dateEnd, &sep, &hour,
                              &minute, &second, &fullEnd);
    const int length = static_cast<int>(text.size());
    const Error bad("date \"" + text + "\" is not YYYY-MM-DD or YYYY-MM-DDTHH:MM:SS", Code::UsageDate);
    // `!(second >= 0 && ...)` also rejects the NaN that %lf reads from "nan".
    if (!((n == 3 && dateEnd == length) || (n == 7 && fullEnd == length && (sep == 'T' || sep == ' '))) ||
        month < 1 || month > 12 || day < 1 || day > 31 || hour < 0 || hour > 23 || minute < 0 || minute > 59 ||
        !(second >= 0 && second < 61))
        return bad;
    std::tm fields{};
    fields.tm_year = year - 1900;
    fields.tm_mon = month - 1;
    fields.tm_mday = day;
    fields.tm_hour = hour;
    fields.tm_min = minute;
    const double whole = static_cast<double>(timegm(&fields));
    // timegm normalises out-of-range days (Feb 30 -> Mar 1); such a date does not exist.
    if (fields.tm_mon != month - 1 || fields.tm_mday != day) return bad;
    return whole + second;
}

}  // namespace toyhost
