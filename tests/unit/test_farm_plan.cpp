// farm/FarmPlan and farm/FarmStatus: the shard spans match --shard, the run options appear once,
// the checkpoint chain exists exactly for stateful shadertoys, the plan refuses options it owns;
// frame lists, patterns and the plan's layout. Pure: no GL, no files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>

#include "farm/FarmPlan.h"
#include "farm/FarmStatus.h"

using namespace toyhost;
using namespace toyhost::farm;

namespace {

PlanRequest request(Scheduler scheduler, bool stateful) {
    PlanRequest r;
    r.scheduler = scheduler;
    r.toyhost = "/opt/toyhost/bin/toyhost";
    r.target = "/srv/ports/my port";
    r.jobDir = "/scratch/job";
    r.frames = 10;
    r.shards = 3;
    r.stateful = stateful;
    r.runOptions = {"--size", "64x36", "--date", "2024-01-01T00:00:00", "--mouse-script", "/srv/drag's.json"};
    return r;
}

const PlanFile* fileNamed(const std::vector<PlanFile>& files, const std::string& name) {
    auto it = std::find_if(files.begin(), files.end(), [&](const PlanFile& f) { return f.name == name; });
    return it == files.end() ? nullptr : &*it;
}

std::size_t count(const std::string& text, const std::string& part) {
    std::size_t n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(FarmPlan, ShardSpansAreThoseOfRunShardAndCoverEveryFrameOnce) {
    // toyhost::shardSpan (toyhost/Shards.h), the one split of --shard i/n, farm plan and Python:
    // frames * i / n .. frames * (i + 1) / n.
    auto span = [](int frames, int shards, int index) {
        Result<FrameSpan> s = shardSpan(frames, shards, index);
        EXPECT_TRUE(s.ok()) << frames << " " << shards << " " << index;
        return s.ok() ? std::pair{s->first, s->end} : std::pair{-1, -1};
    };
    EXPECT_EQ(span(10, 3, 0), (std::pair{0, 3}));
    EXPECT_EQ(span(10, 3, 1), (std::pair{3, 6}));
    EXPECT_EQ(span(10, 3, 2), (std::pair{6, 10}));
    int next = 0;
    for (int i = 0; i < 7; ++i) {
        const auto [first, end] = span(100, 7, i);
        EXPECT_EQ(first, next);
        EXPECT_GE(end - first, 14);
        EXPECT_LE(end - first, 15);
        next = end;
    }
    EXPECT_EQ(next, 100);
    EXPECT_EQ(span(5, 5, 4), (std::pair{4, 5})) << "as many shards as frames: one frame each";
    // No overflow for long runs.
    EXPECT_EQ(span(2000000000, 16, 15), (std::pair{1875000000, 2000000000}));
    // Counts that do not split: more shards than frames, none, an index outside 0 .. shards - 1.
    for (auto [frames, shards, index] : {std::tuple{3, 4, 0}, {0, 1, 0}, {10, 0, 0}, {10, -1, 0}, {10, 3, 3},
                                         {10, 3, -1}, {-5, 1, 0}}) {
        Result<FrameSpan> refused = shardSpan(frames, shards, index);
        ASSERT_FALSE(refused.ok()) << frames << " " << shards << " " << index;
        EXPECT_EQ(refused.error().first().code, Code::Usage);
    }
}

TEST(FarmPlan, RefusesShardCountsThatDoNotSplitItsFrames) {
    PlanRequest r = request(Scheduler::Parallel, false);
    for (int shards : {0, -2, 11}) {
        r.shards = shards;
        Result<std::vector<PlanFile>> files = planFarm(r);
        ASSERT_FALSE(files.ok()) << shards;
        EXPECT_NE(files.error().first().message.find("--shards " + std::to_string(shards)), std::string::npos);
    }
}

TEST(FarmPlan, RunOptionsAppearOnceInRunShardAndEverySchedulerCallsIt) {
    for (Scheduler scheduler : {Scheduler::Slurm, Scheduler::Kubernetes, Scheduler::Parallel}) {
        auto files = planFarm(request(scheduler, false));
        ASSERT_TRUE(files) << files.error().text();
        std::size_t mentions = 0;
        for (const PlanFile& file : *files)
            if (file.name != "farm.json") mentions += count(file.text, "64x36");
        EXPECT_EQ(mentions, 1u);
        const PlanFile* shard = fileNamed(*files, "run-shard.sh");
        ASSERT_NE(shard, nullptr);
        EXPECT_TRUE(shard->executable);
        EXPECT_NE(shard->text.find("options=(--size 64x36 --date 2024-01-01T00:00:00 --mouse-script '/srv/drag'\\''s.json')"),
                  std::string::npos)
            << shard->text;
        EXPECT_NE(shard->text.find("'/srv/ports/my port'"), std::string::npos);
        EXPECT_NE(shard->text.find("firsts=(0 3 6)"), std::string::npos);
        EXPECT_NE(shard->text.find("ends=(3 6 10)"), std::string::npos);
        EXPECT_EQ(fileNamed(*files, "checkpoints.sh"), nullptr);  // no buffers: shards start directly
    }
}

TEST(FarmPlan, SlurmArrayHasOneTaskPerShardAndRequeuesAfterSigterm) {
    PlanRequest r = request(Scheduler::Slurm, false);
    r.slurmTime = "00:01:00";
    r.parallelism = 2;
    auto files = planFarm(r);
    ASSERT_TRUE(files);
    const PlanFile* sbatch = fileNamed(*files, "job.sbatch");
    ASSERT_NE(sbatch, nullptr);
    EXPECT_NE(sbatch->text.find("#SBATCH --array=0-2%2\n"), std::string::npos);
    EXPECT_NE(sbatch->text.find("#SBATCH --time=00:01:00\n"), std::string::npos);
    EXPECT_NE(sbatch->text.find("#SBATCH --requeue\n"), std::string::npos);
    EXPECT_NE(sbatch->text.find("scontrol requeue"), std::string::npos);
    const PlanFile* submit = fileNamed(*files, "submit.sh");
    ASSERT_NE(submit, nullptr);
    EXPECT_EQ(submit->text.find("dependency"), std::string::npos);
}

TEST(FarmPlan, StatefulShadertoysGetACheckpointChainTheShardsStartFrom) {
    auto files = planFarm(request(Scheduler::Slurm, true));
    ASSERT_TRUE(files);
    const PlanFile* chain = fileNamed(*files, "checkpoints.sh");
    ASSERT_NE(chain, nullptr);
    // One step per boundary (shards 1 and 2 start at frames 3 and 6), each resuming the previous.
    EXPECT_NE(chain->text.find("--frames 3 \"${previous[@]}\" --checkpoint \"$job/checkpoints/start-1.ckpt\""),
              std::string::npos)
        << chain->text;
    EXPECT_NE(chain->text.find("--frames 6 \"${previous[@]}\" --checkpoint \"$job/checkpoints/start-2.ckpt\""),
              std::string::npos);
    EXPECT_EQ(count(chain->text, "--checkpoint"), 2u);
    EXPECT_NE(fileNamed(*files, "run-shard.sh")->text.find("start-$index.ckpt"), std::string::npos);
    EXPECT_NE(fileNamed(*files, "submit.sh")->text.find("--dependency=afterok:"), std::string::npos);
    ASSERT_NE(fileNamed(*files, "checkpoints.sbatch"), nullptr);

    auto k8s = planFarm(request(Scheduler::Kubernetes, true));
    ASSERT_TRUE(k8s);
    ASSERT_NE(fileNamed(*k8s, "checkpoints.yaml"), nullptr);
    const std::string& yaml = fileNamed(*k8s, "job.yaml")->text;
    EXPECT_NE(yaml.find("completionMode: Indexed"), std::string::npos);
    EXPECT_NE(yaml.find("completions: 3"), std::string::npos);
    EXPECT_NE(yaml.find("JOB_COMPLETION_INDEX"), std::string::npos);

    // One shard has no boundary: no chain.
    PlanRequest one = request(Scheduler::Parallel, true);
    one.shards = 1;
    auto single = planFarm(one);
    ASSERT_TRUE(single);
    EXPECT_EQ(fileNamed(*single, "checkpoints.sh"), nullptr);
    EXPECT_EQ(fileNamed(*single, "parallel.sh")->text.find("checkpoints.sh"), std::string::npos);
}

TEST(FarmPlan, RefusesWhatItCannotPlan) {
    for (const char* owned : {"--frames", "--shard", "--frame-range", "--resume", "--checkpoint", "--out", "--out=x.png"}) {
        PlanRequest r = request(Scheduler::Parallel, false);
        r.runOptions.push_back(owned);
        auto files = planFarm(r);
        ASSERT_FALSE(files) << owned;
        EXPECT_NE(files.error().text().find(owned), std::string::npos);
    }
    PlanRequest r = request(Scheduler::Parallel, false);
    r.shards = 11;
    EXPECT_FALSE(planFarm(r));
    r = request(Scheduler::Parallel, false);
    r.jobDir = "relative/job";
    EXPECT_FALSE(planFarm(r));
    r = request(Scheduler::Parallel, false);
    r.frameName = "frames.png";
    EXPECT_FALSE(planFarm(r));
}

TEST(FarmPlan, FrameNamesHoldOneNumberAndAnImageExtension) {
    EXPECT_FALSE(frameNameProblem("f_%06d.png"));
    EXPECT_FALSE(frameNameProblem("%d.exr"));
    for (const char* bad : {"f.png", "f_%s.png", "f_%d_%d.png", "sub/f_%04d.png", "f_%04d.mp4", "f_%04d.png%n"})
        EXPECT_TRUE(frameNameProblem(bad)) << bad;
}

TEST(FarmPlan, SchedulerNamesAndShellQuoting) {
    EXPECT_EQ(schedulerNamed("slurm"), Scheduler::Slurm);
    EXPECT_EQ(schedulerNamed("k8s"), Scheduler::Kubernetes);
    EXPECT_EQ(schedulerNamed("parallel"), Scheduler::Parallel);
    EXPECT_FALSE(schedulerNamed("pbs"));
    EXPECT_EQ(shellQuoted("--size"), "--size");
    EXPECT_EQ(shellQuoted(""), "''");
    EXPECT_EQ(shellQuoted("a b"), "'a b'");
    EXPECT_EQ(shellQuoted("it's $HOME"), "'it'\\''s $HOME'");
}

TEST(FarmStatus, PlanLayoutRoundTripsThroughFarmJson) {
    auto files = planFarm(request(Scheduler::Parallel, false));
    ASSERT_TRUE(files);
    auto layout = layoutFromPlan(fileNamed(*files, "farm.json")->text, "/scratch/job");
    ASSERT_TRUE(layout) << layout.error().text();
    EXPECT_EQ(layout->frames, 10);
    EXPECT_EQ(layout->shards, 3);
    EXPECT_EQ(layout->frameFile(7), "/scratch/job/frames/f_000007.png");
    EXPECT_EQ(layout->runOptions.size(), 6u);
    EXPECT_FALSE(layoutFromPlan("[]", "/j"));
    EXPECT_FALSE(layoutFromPlan(R"({"frames": 4, "shards": 2, "frameName": "f_%s.png"})", "/j"));
    EXPECT_FALSE(layoutFromPlan(R"({"frames": 4, "shards": 5, "frameName": "f_%04d.png"})", "/j"));
}

TEST(FarmStatus, FramePatternsListsAndExitCodes) {
    EXPECT_EQ(*framePatternOf({"f_0000.png", "f_0001.png", "notes.txt"}), "f_%04d.png");
    EXPECT_EQ(*framePatternOf({"x00.exr"}), "x%02d.exr");
    EXPECT_FALSE(framePatternOf({"notes.txt"}));
    EXPECT_FALSE(framePatternOf({"a_0001.png", "b_0001.png"}));
    EXPECT_EQ(frameList(std::vector<int>{}), "");
    EXPECT_EQ(frameList(std::vector<int>{3}), "3");
    EXPECT_EQ(frameList(std::vector<int>{3, 7, 8, 9, 12}), "3, 7-9, 12");
    EXPECT_NE(exitMeaning(143).find("SIGTERM"), std::string::npos);
    EXPECT_EQ(exitMeaning(0), "finished");

    FarmStatus status;
    status.shards.push_back({0, {0, 3}, 3, {}, 0});
    EXPECT_TRUE(status.complete());
    status.shards.push_back({1, {3, 6}, 1, {{5, FrameState::Truncated, "x"}, {4, FrameState::Missing, ""}}, 143});
    EXPECT_FALSE(status.complete());
    EXPECT_EQ(frameList(status.badSpans()), "4-5");
}

TEST(FarmStatus, CaptureEveryCountsTheFramesEachShardWrites) {
    PlanRequest r = request(Scheduler::Slurm, false);
    r.runOptions = {"--capture-every", "4"};
    auto files = planFarm(r);
    ASSERT_TRUE(files);
    auto layout = layoutFromPlan(fileNamed(*files, "farm.json")->text, "/j");
    ASSERT_TRUE(layout);
    EXPECT_EQ(layout->captureEvery, 4);
    // Shards of 10 frames: 0-2, 3-5, 6-9. Each shard runs with --frames at its end, so its last
    // frame is written too, besides frames 0, 4 and 8.
    std::vector<int> written;
    for (int i = 0; i < 3; ++i) {
        const FrameSpan span = *shardSpan(10, 3, i);
        for (int f = span.first; f < span.end; ++f)
            if (layout->captured(f, span)) written.push_back(f);
    }
    EXPECT_EQ(written, (std::vector<int>{0, 2, 4, 5, 8, 9}));

    FrameLayout plain;
    plain.frames = 10;
    plain.captureEvery = 4;
    EXPECT_TRUE(plain.captured(9, {6, 10}));
    EXPECT_FALSE(plain.captured(5, {3, 6}));
}

TEST(FarmStatus, ExitCodesComeFromGnuParallelsJoblog) {
    const std::string joblog =
        "Seq\tHost\tStarttime\tJobRuntime\tSend\tReceive\tExitval\tSignal\tCommand\n"
        "1\t:\t1795829646.958\t     1.067\t0\t0\t0\t0\t/j/run-shard.sh 0\n"
        "2\t:\t1795829646.960\t     0.500\t0\t0\t0\t15\t/j/run-shard.sh 1\n"
        "3\t:\t1795829647.059\t     1.063\t0\t0\t1\t0\t/j/run-shard.sh 2\n"
        "4\t:\t1795829650.000\t     1.000\t0\t0\t0\t0\t/j/run-shard.sh 2\n";
    const std::map<int, int> codes = exitCodesFromJoblog(joblog);
    EXPECT_EQ(codes, (std::map<int, int>{{0, 0}, {1, 143}, {2, 0}}));  // the last attempt counts
    EXPECT_TRUE(exitCodesFromJoblog("not a joblog\n").empty());
}

// ---- hostile values (issue 46): nothing a value holds can end a line of a job file ------------

namespace {

// What sbatch makes of the text after "#SBATCH" (its rule, src/sbatch/opt.c): words split at
// unquoted whitespace, ' and " group, a backslash makes the next byte literal but cannot keep an
// unquoted whitespace in the word, an unquoted # ends the line. nullopt: an unmatched quote
// (sbatch exits).
std::optional<std::vector<std::string>> sbatchWords(const std::string& line) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= line.size()) break;
        std::string word;
        char quote = 0;
        bool escape = false, comment = false;
        for (; i < line.size() && (quote || !std::isspace(static_cast<unsigned char>(line[i]))); ++i) {
            const char c = line[i];
            if (escape) {
                escape = false;
                word += c;
            } else if (c == '\\') {
                escape = true;
            } else if (quote) {
                if (c == quote) quote = 0;
                else word += c;
            } else if (c == '\'' || c == '"') {
                quote = c;
            } else if (c == '#') {
                comment = true;
                break;
            } else {
                word += c;
            }
        }
        if (quote) return std::nullopt;
        if (!word.empty()) words.push_back(word);
        if (comment) break;
    }
    return words;
}

// The value of `#SBATCH --NAME=...` in `script`, as sbatch reads it.
std::optional<std::string> sbatchValue(const std::string& script, const std::string& name) {
    std::istringstream in(script);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("#SBATCH", 0) != 0) continue;
        std::optional<std::vector<std::string>> words = sbatchWords(line.substr(7));
        if (!words) return std::nullopt;
        for (const std::string& word : *words)
            if (word.rfind("--" + name + "=", 0) == 0) return word.substr(name.size() + 3);
    }
    return std::nullopt;
}

}  // namespace

TEST(FarmPlan, RefusesLineBreaksNulAndInvalidUtf8InEveryValueItWrites) {
    const std::vector<std::pair<std::string, std::string>> hostile = {
        {"\n", "line break"}, {"\r", "carriage return"}, {std::string(1, '\0'), "NUL"}, {"\xff", "UTF-8"}};
    for (Scheduler scheduler : {Scheduler::Slurm, Scheduler::Kubernetes, Scheduler::Parallel}) {
        for (const auto& [bad, words] : hostile) {
            const std::vector<std::pair<std::string, std::function<void(PlanRequest&)>>> plants = {
                {"--job", [&](PlanRequest& r) { r.jobDir = "/x/job" + bad + "touch PWNED" + bad + "x"; }},
                {"the target", [&](PlanRequest& r) { r.target = "/x/toy" + bad + "touch PWNED"; }},
                {"--toyhost", [&](PlanRequest& r) { r.toyhost = "/opt/toyhost" + bad + "touch PWNED"; }},
                {"--frame-name", [&](PlanRequest& r) { r.frameName = "f" + bad + "_%04d.png"; }},
                {"--time", [&](PlanRequest& r) { r.slurmTime = "1" + bad + "touch PWNED"; }},
                {"--image", [&](PlanRequest& r) { r.image = "toyhost" + bad + "x"; }},
                {"--define", [&](PlanRequest& r) { r.runOptions = {"--define", "X=" + bad}; }},
                {"--mouse-script", [&](PlanRequest& r) { r.runOptions = {"--mouse-script=/x/s" + bad + ".json"}; }},
            };
            for (const auto& [option, plant] : plants) {
                PlanRequest r = request(scheduler, true);
                plant(r);
                Result<std::vector<PlanFile>> files = planFarm(r);
                ASSERT_FALSE(files) << option << " with " << words << " was planned";
                const std::string message = files.error().first().message;
                EXPECT_EQ(files.error().first().code, Code::Usage);
                EXPECT_NE(message.find(option), std::string::npos) << message;
                EXPECT_NE(message.find(words), std::string::npos) << message;
            }
        }
    }
}

TEST(FarmPlan, SbatchDirectivesReadBackAsTheValuesGivenForSlurmsParser) {
    // A space, an apostrophe, a double quote, a backslash-free #, a $ in the job folder: sbatch
    // must read back exactly the folder. Backslashes before the spaces were not enough: sbatch
    // 22.05.8 said "Invalid directive found in batch script: job's".
    PlanRequest r = request(Scheduler::Slurm, true);
    r.jobDir = "/scratch/my job's \"best\" #1 $(touch PWNED)";
    r.slurmTime = "1-02:03:04";
    auto files = planFarm(r);
    ASSERT_TRUE(files) << files.error().text();
    for (const char* name : {"job.sbatch", "checkpoints.sbatch"}) {
        const PlanFile* sbatch = fileNamed(*files, name);
        ASSERT_NE(sbatch, nullptr) << name;
        EXPECT_EQ(sbatchValue(sbatch->text, "output"),
                  std::optional<std::string>("/scratch/my job's \"best\" #1 $(touch PWNED)/logs/%x-%A_%a.log"))
            << sbatch->text;
    }
    EXPECT_EQ(sbatchValue(fileNamed(*files, "job.sbatch")->text, "time"), std::optional<std::string>("1-02:03:04"));
    EXPECT_EQ(sbatchWords(R"( --output=/a/my\ job)"), (std::vector<std::string>{"--output=/a/my", "job"}))
        << "the rule the quoting follows: a backslash does not keep a space in the word";
    // A backslash turns off Slurm's %A/%a in --output: refused for Slurm, fine elsewhere.
    r.jobDir = "/scratch/back\\slash";
    auto refused = planFarm(r);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().text().find("backslash"), std::string::npos);
    r.scheduler = Scheduler::Parallel;
    EXPECT_TRUE(planFarm(r));
    // A % is read by toyhost run --out (and Slurm's log names): refused for every scheduler.
    for (Scheduler scheduler : {Scheduler::Slurm, Scheduler::Kubernetes, Scheduler::Parallel}) {
        PlanRequest percent = request(scheduler, false);
        percent.jobDir = "/scratch/100%";
        auto files = planFarm(percent);
        ASSERT_FALSE(files);
        EXPECT_NE(files.error().text().find("--job: holds a %"), std::string::npos) << files.error().text();
    }
}

TEST(FarmPlan, TheTargetIsNeverWrittenIntoACommentAndPathsAreQuoted) {
    for (Scheduler scheduler : {Scheduler::Slurm, Scheduler::Kubernetes, Scheduler::Parallel}) {
        PlanRequest r = request(scheduler, true);
        r.target = "/srv/toy $(touch PWNED) 'x'";
        auto files = planFarm(r);
        ASSERT_TRUE(files) << files.error().text();
        for (const PlanFile& file : *files) {
            if (file.name == "farm.json") continue;
            std::istringstream in(file.text);
            for (std::string line; std::getline(in, line);)
                if (line.rfind("#", 0) == 0) EXPECT_EQ(line.find("/srv/toy"), std::string::npos) << file.name << ": " << line;
            if (file.text.find("/srv/toy") != std::string::npos)
                EXPECT_NE(file.text.find(R"('/srv/toy $(touch PWNED) '\''x'\''')"), std::string::npos) << file.name;
        }
    }
}

TEST(FarmPlan, TimeIsCheckedAgainstSlurmsFormats) {
    for (const char* good : {"30", "30:00", "1:30:00", "2-0", "2-12", "2-12:30", "2-12:30:15", "0", "UNLIMITED", "infinite"})
        EXPECT_FALSE(slurmTimeProblem(good)) << good;
    for (const char* bad : {"", "1h", "1:2:3:4", "1-2-3", "-5", "1-", ":30", "1::2", "1 ", "12345678901", "1\ntouch PWNED",
                            "1-2:3:4:5", "+5", "0x10"})
        EXPECT_TRUE(slurmTimeProblem(bad)) << bad;
    PlanRequest r = request(Scheduler::Slurm, false);
    r.slurmTime = "one hour";
    auto files = planFarm(r);
    ASSERT_FALSE(files);
    EXPECT_NE(files.error().text().find("--time one hour"), std::string::npos);
    EXPECT_NE(files.error().text().find("DAYS-HOURS:MINUTES:SECONDS"), std::string::npos);
}

TEST(FarmPlan, AFrameNameOfAnyLengthIsCheckedWithoutRecursion) {
    // std::regex recursed once per character: 120,000 characters overflowed the stack (SIGSEGV).
    const std::string huge = std::string(120000, 'a') + "_%04d.png";
    std::optional<std::string> problem = frameNameProblem(huge);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("255"), std::string::npos);
    for (const char* good : {"f_%06d.png", "%d.exr", "f%01d.png", "f%099d.png", "a b_%02d.png"})
        EXPECT_FALSE(frameNameProblem(good)) << good;
    for (const char* bad : {"f_%0d.png", "f_%00d.png", "f_%100d.png", "f_%d", "f_%d.jpg", "%", "%d.png/", "f_%4d.png", "%%d.png"})
        EXPECT_TRUE(frameNameProblem(bad)) << bad;
}

TEST(FarmStatus, FarmJsonCountsAreWholeNumbersReadAsWritten) {
    // nlohmann's get<int>() read 4294967304 as 8 (wrapped) and 8.9 as 8 (truncated): "8/8 frames ok".
    for (const char* frames : {"4294967304", "8.9", "8.0", "-8", "0", "\"8\"", "1e1", "99999999999999999999"}) {
        const std::string json = std::string(R"({"frames": )") + frames + R"(, "shards": 2, "frameName": "f_%04d.png"})";
        auto layout = layoutFromPlan(json, "/j");
        ASSERT_FALSE(layout) << frames;
        const std::string text = layout.error().text();
        EXPECT_NE(text.find("/j/farm.json"), std::string::npos) << text;
        EXPECT_NE(text.find("\"frames\""), std::string::npos) << text;
        EXPECT_EQ(layout.error().first().code, Code::Usage);
    }
    auto shards = layoutFromPlan(R"({"frames": 8, "shards": 2.5, "frameName": "f_%04d.png"})", "/j");
    ASSERT_FALSE(shards);
    EXPECT_NE(shards.error().text().find("\"shards\""), std::string::npos);
    EXPECT_TRUE(layoutFromPlan(R"({"frames": 8, "shards": 2, "frameName": "f_%04d.png"})", "/j"));
}

TEST(FarmStatus, AHostileJoblogIsReadWithoutRegexOrAbort) {
    const std::string header = "Seq\tHost\tStarttime\tJobRuntime\tSend\tReceive\tExitval\tSignal\tCommand\n";
    // A 120 KB command field (std::regex recursed per character: SIGSEGV), an Exitval beyond int
    // (std::stoi threw out_of_range: abort), a shard number beyond int, a signal beyond int; then
    // a good line with a quoted job folder, and a line of tabs.
    const std::string joblog = header + "1\t:\t0\t1\t0\t0\t0\t0\t" + std::string(120000, 'x') + "/run-shard.sh 0\n" +
                               "2\t:\t0\t1\t0\t0\t99999999999\t0\t/j/run-shard.sh 1\n" +
                               "3\t:\t0\t1\t0\t0\t1\t0\t/j/run-shard.sh 99999999999\n" +
                               "4\t:\t0\t1\t0\t0\t1\t99999999999\t/j/run-shard.sh 2\n" +
                               "5\t:\t0\t1\t0\t0\t3\t0\t'/my job'/run-shard.sh 3\n" + std::string(100000, '\t') + "\n" +
                               // parallel -q (parallel.sh) quotes the program's path as one word.
                               "6\t:\t0\t1\t0\t0\t0\t15\t'/my job $(x)/run-shard.sh' 4\n";
    const std::map<int, int> codes = exitCodesFromJoblog(joblog);
    EXPECT_EQ(codes, (std::map<int, int>{{0, 0}, {3, 3}, {4, 143}}));
}

TEST(FarmStatus, FrameListsOfRunsAndCountsWithoutWalkingEveryFrame) {
    EXPECT_EQ(frameList(std::vector<FrameSpan>{}), "");
    EXPECT_EQ(frameList(std::vector<FrameSpan>{{3, 4}, {7, 8}, {8, 10}, {12, 13}}), "3, 7-9, 12");
    EXPECT_EQ(frameList(std::vector<FrameSpan>{{8, 2147483647}}), "8-2147483646");
    FrameLayout layout;
    layout.frames = 2147483647;
    layout.captureEvery = 4;
    const FrameSpan all{0, 2147483647};
    EXPECT_EQ(layout.capturedCount(0, 2147483646, all), 536870912 + 1);  // multiples of 4, and the last
    EXPECT_EQ(layout.firstCaptured(1, 100, all), 4);
    EXPECT_EQ(layout.lastCaptured(1, 100, all), 100);
    EXPECT_EQ(layout.lastCaptured(2147483600, 2147483646, all), 2147483646);
    EXPECT_FALSE(layout.firstCaptured(5, 7, all));
    layout.frameName = "f_%04d.png";
    EXPECT_EQ(layout.frameNumberOf("f_0007.png"), 7);
    EXPECT_EQ(layout.frameNumberOf("f_12345.png"), 12345);
    for (const char* other : {"f_7.png", "f_0007.exr", "g_0007.png", "f_-001.png", "f_99999999999.png", "f_.png"})
        EXPECT_FALSE(layout.frameNumberOf(other)) << other;
}

TEST(FarmPlan, ClusterOptionsAreSbatchLinesOfEveryJobFileQuotedAsTheOtherValues) {
    PlanRequest r = request(Scheduler::Slurm, true);
    r.partition = "gpu nodes";  // read back as one word, as the job folder is
    r.account = "proj's";
    r.qos = "normal";
    r.mem = "16G";
    r.gres = "gpu:a100:1";
    r.schedulerArgs = {"--constraint=avx2&ib", "--exclusive", "--comment=a \"b\""};
    auto files = planFarm(r);
    ASSERT_TRUE(files) << files.error().text();
    for (const char* name : {"job.sbatch", "checkpoints.sbatch"}) {
        const std::string& text = fileNamed(*files, name)->text;
        EXPECT_EQ(sbatchValue(text, "partition"), std::optional<std::string>("gpu nodes")) << text;
        EXPECT_EQ(sbatchValue(text, "account"), std::optional<std::string>("proj's"));
        EXPECT_EQ(sbatchValue(text, "qos"), std::optional<std::string>("normal"));
        EXPECT_EQ(sbatchValue(text, "mem"), std::optional<std::string>("16G"));
        EXPECT_EQ(sbatchValue(text, "gres"), std::optional<std::string>("gpu:a100:1"));
        EXPECT_EQ(sbatchValue(text, "constraint"), std::optional<std::string>("avx2&ib"));
        EXPECT_EQ(sbatchValue(text, "comment"), std::optional<std::string>("a \"b\""));
        EXPECT_NE(text.find("#SBATCH --exclusive\n"), std::string::npos);
    }
    // The same refusals as every other value the plan writes.
    for (std::string PlanRequest::*field : {&PlanRequest::partition, &PlanRequest::account, &PlanRequest::qos}) {
        PlanRequest bad = request(Scheduler::Slurm, false);
        bad.*field = "a\nb";
        auto refused = planFarm(bad);
        ASSERT_FALSE(refused);
        EXPECT_NE(refused.error().text().find("line break"), std::string::npos) << refused.error().text();
    }
    PlanRequest bad = request(Scheduler::Slurm, false);
    bad.schedulerArgs = {"--x=\n"};
    EXPECT_FALSE(planFarm(bad));
    // Not an option, or one the plan's own lines set.
    for (const char* arg : {"constraint=avx2", "--array=0-3", "--time=5", "-o/tmp/x", "--dependency=afterok:1", "--output=x"}) {
        bad.schedulerArgs = {arg};
        auto refused = planFarm(bad);
        ASSERT_FALSE(refused) << arg;
        EXPECT_NE(refused.error().text().find("--scheduler-arg"), std::string::npos) << refused.error().text();
    }
    bad.schedulerArgs.clear();
    for (const char* mem : {"16GB", "G", "lots", "1.5G"}) {
        bad.mem = mem;
        EXPECT_FALSE(planFarm(bad)) << mem;
    }
    for (const char* mem : {"16000", "16G", "512m"}) {
        bad.mem = mem;
        EXPECT_TRUE(planFarm(bad)) << mem;
    }
}

TEST(FarmPlan, KubernetesTakesMemoryAndGpusAsResourcesAndRefusesSlurmsOwn) {
    PlanRequest r = request(Scheduler::Kubernetes, true);
    r.cpusPerTask = 4;
    r.mem = "16G";
    r.gres = "gpu:2";
    auto files = planFarm(r);
    ASSERT_TRUE(files) << files.error().text();
    for (const char* name : {"job.yaml", "checkpoints.yaml"}) {
        const std::string& yaml = fileNamed(*files, name)->text;
        EXPECT_NE(yaml.find("requests: { cpu: \"4\", memory: 16Gi }"), std::string::npos) << yaml;
        EXPECT_NE(yaml.find("limits: { memory: 16Gi, nvidia.com/gpu: \"2\" }"), std::string::npos) << yaml;
    }
    r.mem = "2048";  // sbatch's unit: MiB
    r.gres.clear();
    EXPECT_NE(fileNamed(*planFarm(r), "job.yaml")->text.find("memory: 2048Mi"), std::string::npos);
    PlanRequest refused = request(Scheduler::Kubernetes, false);
    refused.gres = "license:2";
    ASSERT_FALSE(planFarm(refused));
    EXPECT_NE(planFarm(refused).error().text().find("GPUs only"), std::string::npos);
    for (Scheduler scheduler : {Scheduler::Kubernetes, Scheduler::Parallel}) {
        PlanRequest other = request(scheduler, false);
        other.partition = "gpu";
        auto result = planFarm(other);
        ASSERT_FALSE(result);
        EXPECT_NE(result.error().text().find("--partition: Slurm's"), std::string::npos) << result.error().text();
        other = request(scheduler, false);
        other.schedulerArgs = {"--exclusive"};
        EXPECT_FALSE(planFarm(other));
    }
    PlanRequest parallel = request(Scheduler::Parallel, false);
    parallel.mem = "1G";
    EXPECT_FALSE(planFarm(parallel));
}

TEST(FarmPlan, SubmitPassesItsOwnArgumentsToEverySbatch) {
    for (bool stateful : {false, true}) {
        auto files = planFarm(request(Scheduler::Slurm, stateful));
        ASSERT_TRUE(files);
        const std::string& submit = fileNamed(*files, "submit.sh")->text;
        const std::size_t sbatches = count(submit, "sbatch --parsable");
        EXPECT_EQ(sbatches, stateful ? 2u : 1u);
        EXPECT_EQ(count(submit, "\"$@\""), sbatches) << submit;
    }
}

TEST(FarmPlan, TheChainHasItsOwnTimeAndRequeueAndAFailedChainEndsTheArray) {
    PlanRequest r = request(Scheduler::Slurm, true);
    r.slurmTime = "1:30:00";  // 3 shards: the chain simulates 2 shards' frames
    auto files = planFarm(r);
    ASSERT_TRUE(files);
    const std::string& chain = fileNamed(*files, "checkpoints.sbatch")->text;
    EXPECT_EQ(sbatchValue(chain, "time"), std::optional<std::string>("0-03:00:00")) << chain;
    EXPECT_NE(chain.find("#SBATCH --requeue\n"), std::string::npos);
    EXPECT_NE(fileNamed(*files, "submit.sh")->text.find("--dependency=afterok:\"$chain\" --kill-on-invalid-dep=yes"),
              std::string::npos);
    const std::string& array = fileNamed(*files, "job.sbatch")->text;
    EXPECT_EQ(sbatchValue(array, "signal"), std::optional<std::string>("B:TERM@120")) << array;
    EXPECT_NE(array.find("kill -TERM \"$child\""), std::string::npos);
    // Every format sbatch takes; a short limit gets a quarter of it as the lead.
    for (const auto& [time, chainTime, lead] :
         {std::tuple{"5", "0-00:10:00", "B:TERM@75"}, std::tuple{"1", "0-00:02:00", "B:TERM@15"},
          std::tuple{"2-1", "4-02:00:00", "B:TERM@120"}, std::tuple{"10:30", "0-00:21:00", "B:TERM@120"},
          std::tuple{"1-0:0:1", "2-00:00:02", "B:TERM@120"}, std::tuple{"UNLIMITED", "UNLIMITED", "B:TERM@120"}}) {
        r.slurmTime = time;
        auto timed = planFarm(r);
        ASSERT_TRUE(timed) << time;
        EXPECT_EQ(sbatchValue(fileNamed(*timed, "checkpoints.sbatch")->text, "time"), std::optional<std::string>(chainTime)) << time;
        EXPECT_EQ(sbatchValue(fileNamed(*timed, "job.sbatch")->text, "signal"), std::optional<std::string>(lead)) << time;
    }
    r.slurmTime.clear();  // the partition's limit, for both
    EXPECT_FALSE(sbatchValue(fileNamed(*planFarm(r), "checkpoints.sbatch")->text, "time"));
}

TEST(FarmPlan, RedoCommandsAreEachSchedulersOwnForOneShard) {
    EXPECT_EQ(redoCommand(Scheduler::Slurm, "/scratch/my job", 4, false), "sbatch --array=4 '/scratch/my job'/job.sbatch");
    EXPECT_EQ(redoCommand(Scheduler::Slurm, "/j", 0, true), "sbatch --array=0 /j/job.sbatch again");
    EXPECT_EQ(redoCommand(Scheduler::Parallel, "/j", 2, false), "/j/run-shard.sh 2");
    EXPECT_EQ(redoCommand(Scheduler::Parallel, "/j", 2, true), "/j/run-shard.sh 2 again");
    const std::string k8s = redoCommand(Scheduler::Kubernetes, "/j", 1, false);
    EXPECT_NE(k8s.find("kubectl delete --ignore-not-found job/" + kubernetesJobName("render", "/j")), std::string::npos) << k8s;
    EXPECT_NE(k8s.find("kubectl apply -f /j/job.yaml"), std::string::npos);
    // farm status finds the scheduler and the folder in farm.json.
    for (Scheduler scheduler : {Scheduler::Slurm, Scheduler::Kubernetes, Scheduler::Parallel}) {
        auto files = planFarm(request(scheduler, false));
        ASSERT_TRUE(files);
        auto layout = layoutFromPlan(fileNamed(*files, "farm.json")->text, "/scratch/job");
        ASSERT_TRUE(layout);
        EXPECT_EQ(layout->scheduler, std::optional<Scheduler>(scheduler));
        EXPECT_EQ(layout->jobDir, std::filesystem::path("/scratch/job"));
    }
}

TEST(FarmPlan, GnuParallelRunsOneShardAtATimeRetriesAndKeepsSiblingsRunning) {
    PlanRequest r = request(Scheduler::Parallel, true);
    const std::string text = fileNamed(*planFarm(r), "parallel.sh")->text;
    EXPECT_NE(text.find(" -j 1 "), std::string::npos) << text;
    EXPECT_NE(text.find("--retries 3 "), std::string::npos);
    EXPECT_EQ(text.find("--halt"), std::string::npos);
    r.parallelism = 2;
    EXPECT_NE(fileNamed(*planFarm(r), "parallel.sh")->text.find(" -j 2 "), std::string::npos);
}

TEST(FarmPlan, KubernetesJobsAreNamedPerPlanIgnoreDisruptionsAndWarnOfATargetOutside) {
    PlanRequest a = request(Scheduler::Kubernetes, true);
    PlanRequest b = a;
    b.jobDir = "/scratch/job2";
    const std::string nameA = kubernetesJobName("render", a.jobDir), nameB = kubernetesJobName("render", b.jobDir);
    EXPECT_NE(nameA, nameB);
    EXPECT_EQ(nameA.size(), std::string("toyhost-render-").size() + 8);
    auto files = planFarm(a);
    ASSERT_TRUE(files);
    const std::string& job = fileNamed(*files, "job.yaml")->text;
    EXPECT_NE(job.find("  name: " + nameA + "\n"), std::string::npos) << job;
    EXPECT_NE(fileNamed(*files, "checkpoints.yaml")->text.find("  name: " + kubernetesJobName("checkpoints", a.jobDir)),
              std::string::npos);
    EXPECT_NE(job.find("podFailurePolicy:"), std::string::npos);
    EXPECT_NE(job.find("onPodConditions: [{ type: DisruptionTarget }]"), std::string::npos);
    EXPECT_NE(job.find("imagePullPolicy: IfNotPresent"), std::string::npos);
    // The chain's Job failing ends submit.sh's wait with a message, not after 24 h.
    const std::string& submit = fileNamed(*files, "submit.sh")->text;
    EXPECT_NE(submit.find("--for=condition=failed"), std::string::npos) << submit;
    EXPECT_NE(submit.find("exit 1"), std::string::npos);
    // The target (/srv/ports/my port) is outside /scratch/job: a warning; inside: none.
    ASSERT_EQ(planWarnings(a).size(), 1u);
    EXPECT_NE(planWarnings(a)[0].find("outside the job folder"), std::string::npos);
    a.target = "/scratch/job/port";
    EXPECT_TRUE(planWarnings(a).empty());
    a.target = "/scratch/job2/port";  // a sibling folder sharing the prefix is outside
    EXPECT_EQ(planWarnings(a).size(), 1u);
    PlanRequest slurmPlan = request(Scheduler::Slurm, false);
    EXPECT_TRUE(planWarnings(slurmPlan).empty());
}
