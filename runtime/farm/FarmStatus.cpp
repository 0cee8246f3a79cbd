// FarmStatus: the plan's layout, frame lists and their wording (see FarmStatus.h). No GL needed.
#include "farm/FarmStatus.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

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

std::vector<int> FarmStatus::badFrames() const {
    std::vector<int> frames;
    for (const ShardStatus& shard : shards)
        for (const FrameProblem& problem : shard.problems) frames.push_back(problem.frame);
    std::sort(frames.begin(), frames.end());
    return frames;
}

std::filesystem::path FrameLayout::frameFile(int frame) const {
    // frameName was checked to hold exactly one integer conversion.
    char name[4096];
    std::snprintf(name, sizeof name, frameName.c_str(), frame);
    return frameDir / name;
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
    try {
        layout.frames = plan.at("frames").get<int>();
        layout.shards = plan.at("shards").get<int>();
        layout.frameName = plan.at("frameName").get<std::string>();
        if (plan.contains("runOptions")) layout.runOptions = plan.at("runOptions").get<std::vector<std::string>>();
    } catch (const nlohmann::json::exception&) {
        return fileError(where, "expected \"frames\", \"shards\" and \"frameName\" as `toyhost farm plan` writes them",
                         Code::Usage);
    }
    // shardSpan refuses counts that do not split into shards (fewer frames than shards, none).
    if (!shardSpan(layout.frames, layout.shards, 0) || frameNameProblem(layout.frameName))
        return fileError(where, "frames, shards or frameName out of range", Code::Usage);
    layout.frameDir = jobDir / "frames";
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
    // Seq Host Starttime JobRuntime Send Receive Exitval Signal Command, tab-separated.
    static const std::regex line(R"(^[0-9]+\t[^\t]*\t[^\t]*\t[^\t]*\t[^\t]*\t[^\t]*\t(-?[0-9]+)\t([0-9]+)\t.*run-shard\.sh ([0-9]+)\s*$)");
    std::map<int, int> codes;
    std::istringstream in(joblog);
    std::string text;
    while (std::getline(in, text)) {
        std::smatch m;
        if (!std::regex_match(text, m, line)) continue;
        const int signal = std::stoi(m[2].str());
        codes[std::stoi(m[3].str())] = signal ? 128 + signal : std::stoi(m[1].str());
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
