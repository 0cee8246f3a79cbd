// FarmStatus: what a farm's frame folder holds against what its plan expects, shard by shard
// (the states come from sequence/FrameCheck, which reads the files), and the plan a job folder
// records (farm.json). Pure data and text; no GL, no image decoding.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/Result.h"
#include "farm/FarmPlan.h"

namespace toyhost::farm {

enum class FrameState { Ok, Missing, Truncated, Undecodable };
const char* frameStateName(FrameState state);  // "ok", "missing", "truncated", "undecodable"

struct FrameProblem {
    int frame = 0;
    FrameState state = FrameState::Missing;
    std::string reason;  // the decoder's words, for truncated and undecodable frames
    // Missing frames come as one problem per run: every captured frame from `frame` to `last`
    // (`count` of them) is absent. -1: this frame alone.
    int last = -1;
    long long count = 1;
    int lastFrame() const { return last < 0 ? frame : last; }
};

struct ShardStatus {
    int index = 0;
    FrameSpan span;
    int good = 0;
    std::vector<FrameProblem> problems;
    std::optional<int> exitCode;  // what its last attempt exited with, when the job folder records it
    long long expected = 0;       // frames the shard writes (all of its span, or those --capture-every keeps)
    long long bad() const;        // frames not Ok
};

struct FarmStatus {
    std::vector<ShardStatus> shards;
    bool complete() const;
    // Every frame not Ok, ascending, as runs first .. end - 1 (a run of missing frames that
    // --capture-every thins out is one run from its first to its last captured frame).
    std::vector<FrameSpan> badSpans() const;
};

// Where a job's frames are and how they are split: read from farm.json in a folder `farm plan`
// wrote, or given (a plain folder of numbered frames).
struct FrameLayout {
    std::filesystem::path frameDir;
    std::string frameName;  // printf pattern, one %d / %0Nd
    int frames = 0;
    int shards = 1;
    std::vector<std::string> runOptions;
    std::filesystem::path exitDir;  // the shards' exit codes (job.sbatch writes them); empty: none
    std::filesystem::path joblog;   // GNU parallel's job log (parallel.sh); empty: none
    std::filesystem::path jobDir;   // the plan's job folder; empty: a plain folder of frames
    std::optional<Scheduler> scheduler;  // the plan's ("scheduler" of farm.json)
    // --capture-every K among the run options: frames n % K == 0 are written, and the last one of
    // each run, which for a planned shard (run with --frames at its end) is the shard's last.
    int captureEvery = 1;
    bool lastOfEachShard = false;
    std::filesystem::path frameFile(int frame) const;
    // The frame number a file name of frameDir stands for, when it is one of this layout's names.
    std::optional<int> frameNumberOf(const std::string& name) const;
    // How many frames of `span` are written, and the first and last of them from `from` to `to`
    // (inclusive; nullopt when none is): arithmetic, so that a span of 2^31 frames costs nothing.
    long long capturedCount(int from, int to, FrameSpan span) const;
    std::optional<int> firstCaptured(int from, int to, FrameSpan span) const;
    std::optional<int> lastCaptured(int from, int to, FrameSpan span) const;
    // Whether `frame` of the shard `span` is written at all.
    bool captured(int frame, FrameSpan span) const;
};

// farm.json's text (from planFarm) into the layout of the job folder `jobDir`. "frames" and
// "shards" must be JSON integers within 1..INT_MAX (8.9 or 4294967304 is an error naming the
// field, never truncated or wrapped).
Result<FrameLayout> layoutFromPlan(const std::string& json, const std::filesystem::path& jobDir);

// The numbered-frame pattern the file `names` of a folder follow ("f_%04d.png"): the one prefix,
// digit count and extension (.png or .exr) the numbered files share; an error when there are none
// or several.
Result<std::string> framePatternOf(const std::vector<std::string>& names);

// "3, 7-9, 12": ascending frame numbers, runs shortened.
std::string frameList(const std::vector<int>& frames);
// The same for runs first .. end - 1 (adjacent runs joined).
std::string frameList(const std::vector<FrameSpan>& runs);

// Shard -> exit code from GNU parallel's --joblog text (parallel.sh writes logs/parallel.log): the
// last line of each `run-shard.sh INDEX`; a signal as 128 + its number, as a shell reports it.
std::map<int, int> exitCodesFromJoblog(const std::string& joblog);

// What an exit code of `toyhost run` means ("stopped by SIGTERM", "the watchdog", ...).
std::string exitMeaning(int code);

}  // namespace toyhost::farm
