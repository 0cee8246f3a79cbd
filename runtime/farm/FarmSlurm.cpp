// FarmSlurm: job.sbatch, checkpoints.sbatch and submit.sh of a plan (see FarmSlurm.h).
#include "farm/FarmSlurm.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <sstream>
#include <string_view>
#include <vector>

namespace toyhost::farm::slurm {

namespace {

// The options the plan's own lines set: given again as a --scheduler-arg, the job would break.
constexpr const char* kOwnedOptions[] = {"--array", "-a", "--output", "-o", "--error", "-e", "--open-mode",
                                         "--job-name", "-J", "--dependency", "-d", "--time", "-t", "--signal",
                                         "--kill-on-invalid-dep", "--parsable"};

std::string header(const PlanRequest& r, const std::string& name, const std::string& time) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "#SBATCH --job-name=" << name << "\n"
      << "#SBATCH --output=" << directiveWord(r.jobDir + "/logs/%x-%A_%a.log") << "\n"
      << "#SBATCH --open-mode=append\n";
    if (!time.empty()) s << "#SBATCH --time=" << directiveWord(time) << "\n";
    if (r.cpusPerTask > 0) s << "#SBATCH --cpus-per-task=" << r.cpusPerTask << "\n";
    const std::pair<const char*, const std::string*> cluster[] = {
        {"partition", &r.partition}, {"account", &r.account}, {"qos", &r.qos}, {"mem", &r.mem}, {"gres", &r.gres}};
    for (const auto& [name, value] : cluster)
        if (!value->empty()) s << "#SBATCH --" << name << "=" << directiveWord(*value) << "\n";
    for (const std::string& arg : r.schedulerArgs) s << "#SBATCH " << directiveWord(arg) << "\n";
    return s.str();
}

}  // namespace

// As sbatch reads it (src/sbatch/opt.c, _get_argument, Slurm 22.05): whitespace ends a word, ' and
// " group, an unquoted # starts a comment, and a backslash makes the next byte literal, except
// whitespace outside quotes, which ends the word all the same (a job folder "my\ job" was read as
// two words: "Invalid directive found in batch script: job's", seen on Slurm 22.05.8). So a value
// that is not plain goes in double quotes, with \ and " escaped.
std::string directiveWord(const std::string& text) {
    const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || std::string_view("_-+=./:,@%").find(c) != std::string_view::npos;
    });
    if (plain) return text;
    std::string word = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') word += '\\';
        word += c;
    }
    return word + '"';
}

std::optional<long long> seconds(const std::string& text) {
    if (text.empty() || slurmTimeProblem(text)) return std::nullopt;
    if (!std::isdigit(static_cast<unsigned char>(text.front()))) return std::nullopt;  // UNLIMITED
    long long days = 0;
    std::string_view rest = text;
    const std::size_t dash = rest.find('-');
    if (dash != std::string_view::npos) {
        days = std::stoll(std::string(rest.substr(0, dash)));
        rest = rest.substr(dash + 1);
    }
    std::vector<long long> fields;
    for (std::size_t colon; (colon = rest.find(':')) != std::string_view::npos; rest = rest.substr(colon + 1))
        fields.push_back(std::stoll(std::string(rest.substr(0, colon))));
    fields.push_back(std::stoll(std::string(rest)));
    // Slurm's reading: MINUTES[:SECONDS] or HOURS:MINUTES:SECONDS; after DAYS-: HOURS[:MINUTES[:SECONDS]].
    long long h = 0, m = 0, sec = 0;
    if (dash != std::string_view::npos) {
        h = fields[0];
        if (fields.size() > 1) m = fields[1];
        if (fields.size() > 2) sec = fields[2];
    } else if (fields.size() == 3) {
        h = fields[0], m = fields[1], sec = fields[2];
    } else {
        m = fields[0];
        if (fields.size() > 1) sec = fields[1];
    }
    return ((days * 24 + h) * 60 + m) * 60 + sec;
}

std::string chainTime(const PlanRequest& r) {
    const std::optional<long long> shard = seconds(r.slurmTime);
    if (!shard) return r.slurmTime;  // empty (the partition's limit) or UNLIMITED
    // The chain simulates frames 0 .. the last shard's first: (K-1)/K of the run, what K-1 shards
    // take, minus the image writes; at least one shard's limit.
    const long long total = *shard * std::max(1, r.shards - 1);
    const long long days = total / 86400, h = total / 3600 % 24, m = total / 60 % 60, sec = total % 60;
    char text[48];
    std::snprintf(text, sizeof text, "%lld-%02lld:%02lld:%02lld", days, h, m, sec);
    return text;
}

int signalLead(const PlanRequest& r) {
    // Two minutes: time for a frame in flight on llvmpipe and the checkpoint's write; a quarter of
    // a shorter limit (Slurm checks its timers about every 30 s, so a lead must not eat the run).
    constexpr long long kLead = 120;
    const std::optional<long long> limit = seconds(r.slurmTime);
    return static_cast<int>(limit ? std::clamp(*limit / 4, 1LL, kLead) : kLead);
}

std::optional<std::string> optionsProblem(const PlanRequest& r) {
    if (!r.mem.empty()) {
        const std::size_t digits = r.mem.find_first_not_of("0123456789");
        const bool unit = digits != std::string::npos && digits + 1 == r.mem.size() &&
                          std::string_view("KMGTkmgt").find(r.mem.back()) != std::string_view::npos;
        if (digits == 0 || (digits != std::string::npos && !unit))
            return "--mem " + r.mem + ": expected a size as sbatch --mem takes it: digits with an optional K, M, G or T (16G)";
    }
    for (const std::string& arg : r.schedulerArgs) {
        if (arg.size() < 2 || arg.front() != '-')
            return "--scheduler-arg " + arg + ": expected one sbatch option as one word (--constraint=avx2)";
        const std::string name = arg.substr(0, arg.find('='));
        for (const char* owned : kOwnedOptions)
            if (name == owned || (name.size() > 2 && name[1] != '-' && name.compare(0, 2, owned) == 0))
                return "--scheduler-arg " + arg + ": farm plan sets " + owned +
                       " itself (--time has its own option; the rest are the job's structure)";
    }
    return std::nullopt;
}

std::string arrayFile(const PlanRequest& r) {
    std::ostringstream s;
    s << header(r, "toyhost", r.slurmTime) << "#SBATCH --array=0-" << r.shards - 1;
    if (r.parallelism > 0) s << '%' << r.parallelism;
    const int lead = signalLead(r);
    s << "\n"
      << "#SBATCH --requeue\n"
      << "#SBATCH --signal=B:TERM@" << lead << "\n"
      << "# One array task per shard. " << lead << " s before its time limit Slurm sends SIGTERM to this\n"
      << "# shell, which passes it on once: toyhost writes the shard's checkpoint and exits 143, and the\n"
      << "# task asks to be requeued; the next attempt resumes.\n"
      << "job=" << shellQuoted(r.jobDir) << "\n"
      << "task=$SLURM_ARRAY_TASK_ID\n"
      << "child='' stopping=''\n"
      << "# At the limit itself Slurm signals every process of the task: this shell only outlives it.\n"
      << "trap 'if [ -z \"$stopping\" ] && [ -n \"$child\" ]; then stopping=1;"
         " echo \"job.sbatch: SIGTERM ahead of the time limit: stopping shard $task\" >&2;"
         " kill -TERM \"$child\" 2>/dev/null; fi' TERM\n"
      << "\"$job/run-shard.sh\" \"$task\" \"$@\" &\n"
      << "child=$!\n"
      << "wait \"$child\"; code=$?\n"
      << "while kill -0 \"$child\" 2>/dev/null; do wait \"$child\"; code=$?; done\n"
      << "echo \"$code\" > \"$job/exit/shard-$task\"\n"
      << "if [ \"$code\" -eq 143 ] && [ -s \"$job/checkpoints/shard-$task.ckpt\" ]; then\n"
      << "  scontrol requeue \"${SLURM_ARRAY_JOB_ID}_${task}\"\n"
      << "fi\n"
      << "exit \"$code\"\n";
    return s.str();
}

std::string chainFile(const PlanRequest& r) {
    // Requeued after a node failure or preemption: checkpoints.sh skips the boundaries it has.
    return header(r, "toyhost-checkpoints", chainTime(r)) + "#SBATCH --requeue\nexec " + shellQuoted(r.jobDir) +
           "/checkpoints.sh\n";
}

std::string submitFile(const PlanRequest& r) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# Submits the job (the checkpoint chain first, for a stateful shadertoy); prints the array's job id.\n"
      << "# Its arguments go to every sbatch (submit.sh --account=x --partition=y): they override the files'.\n"
      << "set -eu\n"
      << "job=" << shellQuoted(r.jobDir) << "\n"
      << "mkdir -p \"$job/logs\"\n";
    if (r.stateful)
        s << "chain=$(sbatch --parsable \"$@\" \"$job/checkpoints.sbatch\")\n"
          << "# A failed chain cancels the array (its state: DependencyNeverSatisfied, then CANCELLED).\n"
          << "sbatch --parsable --dependency=afterok:\"$chain\" --kill-on-invalid-dep=yes \"$@\" \"$job/job.sbatch\"\n";
    else
        s << "sbatch --parsable \"$@\" \"$job/job.sbatch\"\n";
    return s.str();
}

}  // namespace toyhost::farm::slurm
