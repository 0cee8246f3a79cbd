// FarmStatus: the plan's layout, frame lists and their wording (see FarmStatus.h). No GL needed.
#include "farm/FarmStatus.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>
#include <cstdio>
#include <map>
#include <limits>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "core/JsonText.h"
#include "core/NumberText.h"

namespace toyhost::farm {

const char* frameStateName(FrameState state) {
    switch (state) {
    case FrameState::Ok: return "ok";
    case FrameState::Missing: return "missing";
    case FrameState::Truncated: return "truncated";
    case FrameState::Undecodable: return "undecodable";
    }
    return "?";
}

bool FarmStatus::complete() const {
    return std::all_of(shards.begin(), shards.end(), [](const ShardStatus& s) { return s.problems.empty(); });
}

long long ShardStatus::bad() const {
    long long n = 0;
    for (const FrameProblem& problem : problems) n += problem.count;
    return n;
}

std::vector<FrameSpan> FarmStatus::badSpans() const {
    std::vector<FrameSpan> runs;
    for (const ShardStatus& shard : shards)
        for (const FrameProblem& problem : shard.problems) runs.push_back({problem.frame, problem.lastFrame() + 1});
    std::sort(runs.begin(), runs.end(), [](FrameSpan a, FrameSpan b) { return a.first < b.first; });
    return runs;
}

std::filesystem::path FrameLayout::frameFile(int frame) const {
    // frameName was checked to hold exactly one integer conversion.
    char name[4096];
    std::snprintf(name, sizeof name, frameName.c_str(), frame);
    return frameDir / name;
}

std::optional<int> FrameLayout::frameNumberOf(const std::string& name) const {
    const std::size_t percent = frameName.find('%');
    const std::size_t conversion = frameName.find('d', percent);
    if (percent == std::string::npos || conversion == std::string::npos) return std::nullopt;
    const std::string prefix = frameName.substr(0, percent), suffix = frameName.substr(conversion + 1);
    if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return std::nullopt;
    const std::optional<long long> number =
        parseDecimalInteger(std::string_view(name).substr(prefix.size(), name.size() - prefix.size() - suffix.size()));
    if (!number || *number < 0 || *number > std::numeric_limits<int>::max()) return std::nullopt;
    // Only the name the frame is written under (f_0007.png, not f_7.png for f_%04d.png).
    if (frameFile(static_cast<int>(*number)).filename() != name) return std::nullopt;
    return static_cast<int>(*number);
}

namespace {
// Multiples of `every` from `from` to `to` (inclusive, from <= to, both >= 0).
long long multiples(long long from, long long to, long long every) { return to / every - (from + every - 1) / every + 1; }
}  // namespace

long long FrameLayout::capturedCount(int from, int to, FrameSpan span) const {
    if (from > to) return 0;
    const long long end = lastOfEachShard ? span.end : frames;
    const long long every = std::max(captureEvery, 1);
    long long n = multiples(from, to, every);
    if (end - 1 >= from && end - 1 <= to && (end - 1) % every != 0) ++n;
    return n;
}

std::optional<int> FrameLayout::firstCaptured(int from, int to, FrameSpan span) const {
    if (from > to) return std::nullopt;
    const long long every = std::max(captureEvery, 1), last = (lastOfEachShard ? span.end : frames) - 1;
    long long first = (from + every - 1) / every * every;
    if (last >= from && last <= to) first = std::min(first, last);
    if (first > to) return std::nullopt;
    return static_cast<int>(first);
}

std::optional<int> FrameLayout::lastCaptured(int from, int to, FrameSpan span) const {
    if (from > to) return std::nullopt;
    const long long every = std::max(captureEvery, 1), last = (lastOfEachShard ? span.end : frames) - 1;
    if (last >= from && last <= to) return static_cast<int>(last);
    const long long found = static_cast<long long>(to) / every * every;
    if (found < from) return std::nullopt;
    return static_cast<int>(found);
}

bool FrameLayout::captured(int frame, FrameSpan span) const {
    return capturedFrame(frame, lastOfEachShard ? span.end : frames, captureEvery);
}

namespace {

// --capture-every K (or --capture-every=K) among run options; 1 when absent or unreadable (the
// plan checked them with toyhost run's own parser).
int captureEveryOption(const std::vector<std::string>& options) {
    for (std::size_t i = 0; i < options.size(); ++i) {
        std::string value;
        if (options[i] == "--capture-every" && i + 1 < options.size()) value = options[i + 1];
        else if (options[i].rfind("--capture-every=", 0) == 0) value = options[i].substr(16);
        else continue;
        try {
            const int every = std::stoi(value);
            return every >= 1 ? every : 1;
        } catch (const std::exception&) {
            return 1;
        }
    }
    return 1;
}

}  // namespace

Result<FrameLayout> layoutFromPlan(const std::string& json, const std::filesystem::path& jobDir) {
    const nlohmann::json plan = nlohmann::json::parse(json, nullptr, false);
    const std::string where = (jobDir / "farm.json").string();
    if (plan.is_discarded() || !plan.is_object())
        return fileError(where, "not a plan written by `toyhost farm plan` (not a JSON object)", Code::Usage);
    FrameLayout layout;
    // Counts as whole numbers of int's range, read as written: 8.9 or 4294967304 is refused, not
    // truncated or wrapped to 8.
    for (const auto& [field, target] : {std::pair{"frames", &layout.frames}, std::pair{"shards", &layout.shards}}) {
        if (!plan.contains(field))
            return fileError(where, std::string("has no \"") + field + "\" (a plan written by `toyhost farm plan` has one)",
                             Code::Usage);
        const std::optional<long long> number = jsonWholeNumber(plan.at(field), 1, std::numeric_limits<int>::max());
        if (!number)
            return fileError(where, std::string("\"") + field + "\" must be a whole number from 1 to " +
                                        std::to_string(std::numeric_limits<int>::max()) + ", not " +
                                        describeJsonValue(plan.at(field)),
                             Code::Usage);
        *target = static_cast<int>(*number);
    }
    try {
        layout.frameName = plan.at("frameName").get<std::string>();
        if (plan.contains("scheduler")) layout.scheduler = schedulerNamed(plan.at("scheduler").get<std::string>());
        if (plan.contains("runOptions")) layout.runOptions = plan.at("runOptions").get<std::vector<std::string>>();
    } catch (const nlohmann::json::exception&) {
        return fileError(where, "expected \"frameName\" (a string) and \"runOptions\" (strings) as `toyhost farm plan` writes them",
                         Code::Usage);
    }
    // shardSpan refuses counts that do not split into shards (fewer frames than shards).
    if (!shardSpan(layout.frames, layout.shards, 0))
        return fileError(where, "\"shards\" " + std::to_string(layout.shards) + " does not split \"frames\" " +
                                    std::to_string(layout.frames) + " (1 .. frames)",
                         Code::Usage);
    if (std::optional<std::string> problem = frameNameProblem(layout.frameName))
        return fileError(where, "\"frameName\": " + *problem, Code::Usage);
    layout.frameDir = jobDir / "frames";
    layout.jobDir = jobDir;
    layout.exitDir = jobDir / "exit";
    layout.joblog = jobDir / "logs/parallel.log";
    layout.captureEvery = captureEveryOption(layout.runOptions);
    layout.lastOfEachShard = true;
    return layout;
}

Result<std::string> framePatternOf(const std::vector<std::string>& names) {
    static const std::regex numbered(R"(^([^%]*?)([0-9]+)\.(png|exr)$)");
    std::map<std::string, int> patterns;  // pattern -> files
    for (const std::string& name : names) {
        std::smatch m;
        if (!std::regex_match(name, m, numbered)) continue;
        const std::string digits = m[2].str();
        // A number with a leading zero (or as wide as all of them) was padded; one without is %d
        // only if nothing else in the folder pads.
        patterns[m[1].str() + "%0" + std::to_string(digits.size()) + "d." + m[3].str()]++;
    }
    if (patterns.empty()) return Error("no numbered .png or .exr frames (f_0001.png) in the folder", Code::IoNotFound);
    if (patterns.size() > 1) {
        std::string list;
        for (const auto& [pattern, count] : patterns) {
            if (!list.empty()) list += ", ";
            list += pattern;
        }
        return Error("the folder holds several frame sequences (" + list + "): give the one to check with --pattern",
                     Code::Usage);
    }
    return patterns.begin()->first;
}

std::string frameList(const std::vector<FrameSpan>& runs) {
    std::string text;
    for (std::size_t i = 0; i < runs.size();) {
        std::size_t j = i;
        int end = runs[i].end;
        while (j + 1 < runs.size() && runs[j + 1].first <= end) end = std::max(end, runs[++j].end);
        if (!text.empty()) text += ", ";
        text += std::to_string(runs[i].first);
        if (end - 1 > runs[i].first) {
            text += '-';
            text += std::to_string(end - 1);
        }
        i = j + 1;
    }
    return text;
}

std::string frameList(const std::vector<int>& frames) {
    std::string text;
    for (std::size_t i = 0; i < frames.size();) {
        std::size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        if (!text.empty()) text += ", ";
        text += std::to_string(frames[i]);
        if (j > i) {
            text += '-';
            text += std::to_string(frames[j]);
        }
        i = j + 1;
    }
    return text;
}

std::map<int, int> exitCodesFromJoblog(const std::string& joblog) {
    // Seq Host Starttime JobRuntime Send Receive Exitval Signal Command, tab-separated. Split by
    // hand, not with std::regex, whose matcher recurses per character and overflowed the stack on
    // a 120 KB command field; numbers outside int's range make the line unreadable, not an abort.
    auto number = [](std::string_view text, long long min, long long max) -> std::optional<int> {
        const std::optional<long long> n = parseDecimalInteger(text);
        if (!n || *n < min || *n > max) return std::nullopt;
        return static_cast<int>(*n);
    };
    std::map<int, int> codes;
    std::string_view rest = joblog;
    while (!rest.empty()) {
        const std::size_t newline = rest.find('\n');
        std::string_view line = rest.substr(0, newline);
        rest = newline == std::string_view::npos ? std::string_view() : rest.substr(newline + 1);
        std::vector<std::string_view> fields;
        for (std::size_t tab; fields.size() < 8 && (tab = line.find('\t')) != std::string_view::npos; line = line.substr(tab + 1))
            fields.push_back(line.substr(0, tab));
        if (fields.size() < 8 || !number(fields[0], 0, std::numeric_limits<int>::max())) continue;
        std::string_view command = line;  // the rest: the command, tabs and all
        while (!command.empty() && std::isspace(static_cast<unsigned char>(command.back()))) command.remove_suffix(1);
        const std::size_t space = command.rfind(' ');
        // parallel -q writes the command's words quoted: '/my job/run-shard.sh' 3.
        const std::string_view program = space == std::string_view::npos ? std::string_view() : command.substr(0, space);
        if (!program.ends_with("run-shard.sh") && !program.ends_with("run-shard.sh'")) continue;
        const std::optional<int> shard = number(command.substr(space + 1), 0, std::numeric_limits<int>::max());
        const std::optional<int> exitval = number(fields[6], -255, 255);
        const std::optional<int> signal = number(fields[7], 0, 127);
        if (!shard || !exitval || !signal) continue;
        codes[*shard] = *signal ? 128 + *signal : *exitval;
    }
    return codes;
}

std::string exitMeaning(int code) {
    switch (code) {
    case 0: return "finished";
    case 1: return "failed";
    case 2: return "bad usage";
    case 124: return "stopped by the watchdog";
    case 129: return "stopped by SIGHUP";
    case 130: return "stopped by SIGINT";
    case 143: return "stopped by SIGTERM (a time limit or preemption: resumes from its checkpoint)";
    default: return code > 128 ? "killed by signal " + std::to_string(code - 128) : "exit " + std::to_string(code);
    }
}

}  // namespace toyhost::farm
