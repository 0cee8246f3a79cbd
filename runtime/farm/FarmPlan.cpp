// FarmPlan: writes the scheduler files of a sharded render as text (see FarmPlan.h). The run's
// options live only in run-shard.sh, so every scheduler runs the same command. No GL needed.
#include "farm/FarmPlan.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/JsonText.h"
#include "farm/FarmSlurm.h"

namespace toyhost::farm {

namespace {

std::string joinQuoted(const std::vector<std::string>& words) {
    std::string text;
    for (const std::string& word : words) {
        if (!text.empty()) text += ' ';
        text += shellQuoted(word);
    }
    return text;
}

// The options the plan itself sets for every shard: given again, two values would fight.
std::optional<std::string> ownedOption(const std::vector<std::string>& options) {
    for (const std::string& option : options)
        for (const char* owned : {"--frames", "--shard", "--frame-range", "--resume", "--checkpoint", "--out", "--window",
                                  "--watch"})
            if (option == owned || option.rfind(std::string(owned) + "=", 0) == 0) return option;
    return std::nullopt;
}

std::string yamlQuoted(const std::string& text) {
    // A JSON string is a YAML double-quoted scalar.
    return nlohmann::json(text).dump();
}

std::string farmJson(const PlanRequest& r, const std::vector<FrameSpan>& shardSpans) {
    nlohmann::json spans = nlohmann::json::array();
    for (const FrameSpan& span : shardSpans) spans.push_back({span.first, span.end});
    const char* scheduler = r.scheduler == Scheduler::Slurm ? "slurm" : r.scheduler == Scheduler::Kubernetes ? "k8s" : "parallel";
    nlohmann::json plan = {{"target", r.target}, {"frames", r.frames},    {"shards", r.shards},
                           {"frameName", r.frameName}, {"spans", spans}, {"scheduler", scheduler},
                           {"stateful", r.stateful}, {"runOptions", r.runOptions}};
    return plan.dump(2) + "\n";
}

std::string bashArray(const std::vector<int>& values) {
    std::string text = "(";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (i) text += ' ';
        text += std::to_string(values[i]);
    }
    text += ')';
    return text;
}

// run-shard.sh INDEX: the one place the run's command and options are written. It resumes from the
// shard's own checkpoint when a previous attempt left one (a requeued task), else from the chain's
// checkpoint at the shard's first frame (stateful), else starts at the first frame directly.
std::string runShardScript(const PlanRequest& r, const std::vector<FrameSpan>& spans) {
    std::vector<int> firsts, ends;
    for (const FrameSpan& span : spans) {
        firsts.push_back(span.first);
        ends.push_back(span.end);
    }
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# One shard of the run (" << r.frames << " frames in " << r.shards
      << " shards), written by `toyhost farm plan`: run-shard.sh INDEX.\n"
      << "set -u\n"
      << "index=\"${1:?usage: run-shard.sh INDEX}\"\n"
      << "job=" << shellQuoted(r.jobDir) << "\n"
      << "firsts=" << bashArray(firsts) << "\n"
      << "ends=" << bashArray(ends) << "\n"
      << "if ! [[ \"$index\" =~ ^[0-9]+$ ]] || ((index >= " << r.shards << ")); then\n"
      << "  echo \"run-shard.sh: no shard $index (0.." << r.shards - 1 << ")\" >&2; exit 2\n"
      << "fi\n"
      << "first=${firsts[index]} end=${ends[index]}\n"
      << "options=(" << joinQuoted(r.runOptions) << ")\n"
      << "own=\"$job/checkpoints/shard-$index.ckpt\"\n"
      << "mkdir -p \"$job/frames\" \"$job/checkpoints\" \"$job/exit\"\n"
      << "# `again`: render the whole shard anew (frames lost or damaged after it finished).\n"
      << "if [ \"${2:-}\" = again ]; then rm -f \"$own\"; fi\n"
      << "# A checkpoint holds the next frame to render: resuming from it without a range renders\n"
      << "# from there to --frames, the shard's end. The shard's own one is left by an attempt that\n"
      << "# was stopped (a time limit, preemption: SIGTERM) or by one that finished.\n"
      << "start=(--frame-range \"$first:$end\")\n"
      << "if [ -s \"$own\" ]; then\n"
      << "  start=(--resume \"$own\")\n";
    if (r.stateful)
        s << "elif ((index > 0)); then\n"
          << "  start=(--resume \"$job/checkpoints/start-$index.ckpt\")\n";
    s << "fi\n"
      << "echo \"run-shard.sh: shard $index, frames $first-$((end - 1)): ${start[*]}\" >&2\n"
      << "# exec: toyhost itself receives the scheduler's SIGTERM (a wrapper that forwarded it would\n"
      << "# deliver a second one where the scheduler signals every process, which stops at once).\n"
      << "exec " << shellQuoted(r.toyhost) << " run " << shellQuoted(r.target)
      << " --headless --quiet --frames \"$end\" \"${start[@]}\" --checkpoint \"$own\" \"${options[@]}\" \\\n"
      << "  --out \"$job/frames/\"" << shellQuoted(r.frameName) << "\n";
    return s.str();
}

// checkpoints.sh: one sequential pass over the boundaries, each step simulating only its part.
std::string chainScript(const PlanRequest& r, const std::vector<FrameSpan>& spans) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# The checkpoint at each shard's first frame: one sequential pass, each\n"
      << "# step simulating only the frames since the previous one. Written by `toyhost farm plan`.\n"
      << "set -eu\n"
      << "job=" << shellQuoted(r.jobDir) << "\n"
      << "options=(" << joinQuoted(r.runOptions) << ")\n"
      << "mkdir -p \"$job/checkpoints\"\n"
      << "previous=()\n";
    for (int i = 1; i < r.shards; ++i) {
        const FrameSpan& span = spans[static_cast<std::size_t>(i)];
        const std::string file = "\"$job/checkpoints/start-" + std::to_string(i) + ".ckpt\"";
        s << "if [ ! -s " << file << " ]; then\n"
          << "  " << shellQuoted(r.toyhost) << " run " << shellQuoted(r.target) << " --headless --quiet --frames "
          << span.first << " \"${previous[@]}\" --checkpoint " << file << " \"${options[@]}\"\n"
          << "fi\n"
          << "previous=(--resume " << file << ")\n";
    }
    return s.str();
}

// Slurm's --mem (MiB without a unit, K/M/G/T: powers of 1024) as a Kubernetes quantity.
std::string k8sMemory(const std::string& mem) {
    const char unit = static_cast<char>(std::toupper(static_cast<unsigned char>(mem.back())));
    if (std::isdigit(static_cast<unsigned char>(unit))) return mem + "Mi";
    return mem.substr(0, mem.size() - 1) + unit + "i";
}

// GPUs of a --gres gpu:N or gpu:TYPE:N, or nothing when it names another resource.
std::optional<std::string> gresGpus(const std::string& gres) {
    if (gres.rfind("gpu:", 0) != 0) return std::nullopt;
    const std::string count = gres.substr(gres.rfind(':') + 1);
    if (count.empty() || count.size() > 6 || count.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return count;
}

// requests (cpu, memory) and limits (memory, GPUs: Kubernetes takes these as limits only).
std::string k8sResources(const PlanRequest& r) {
    std::vector<std::string> requests, limits;
    if (r.cpusPerTask > 0) requests.push_back("cpu: \"" + std::to_string(r.cpusPerTask) + "\"");
    if (!r.mem.empty()) {
        requests.push_back("memory: " + k8sMemory(r.mem));
        limits.push_back("memory: " + k8sMemory(r.mem));
    }
    if (!r.gres.empty()) limits.push_back("nvidia.com/gpu: \"" + gresGpus(r.gres).value_or("") + "\"");
    if (requests.empty() && limits.empty()) return "";
    auto map = [](const std::vector<std::string>& entries) {
        std::string text = "{ ";
        for (std::size_t i = 0; i < entries.size(); ++i) text += (i ? ", " : "") + entries[i];
        return text + " }";
    };
    std::string text = "          resources:\n";
    if (!requests.empty()) text += "            requests: " + map(requests) + "\n";
    if (!limits.empty()) text += "            limits: " + map(limits) + "\n";
    return text;
}

std::string k8sJob(const PlanRequest& r, const std::string& name, bool indexed, const std::string& command) {
    std::ostringstream s;
    s << "apiVersion: batch/v1\n"
      << "kind: Job\n"
      << "metadata:\n"
      << "  name: " << name << "\n"
      << "spec:\n";
    if (indexed)
        s << "  completionMode: Indexed\n"
          << "  completions: " << r.shards << "\n"
          << "  parallelism: " << (r.parallelism > 0 ? r.parallelism : r.shards) << "\n"
          << "  backoffLimitPerIndex: 2\n";
    s << "  backoffLimit: " << (indexed ? 2 * r.shards : 2) << "\n"
      << "  # A pod evicted, preempted or lost with its node is not the shard's fault: no retry is used up.\n"
      << "  podFailurePolicy:\n"
      << "    rules:\n"
      << "      - action: Ignore\n"
      << "        onPodConditions: [{ type: DisruptionTarget }]\n"
      << "  template:\n"
      << "    spec:\n"
      << "      restartPolicy: Never\n"
      << "      terminationGracePeriodSeconds: 30\n"
      << "      containers:\n"
      << "        - name: toyhost\n"
      << "          image: " << yamlQuoted(r.image) << "\n"
      << "          imagePullPolicy: IfNotPresent\n"
      << "          command: [\"bash\", \"-c\", " << yamlQuoted(command) << "]\n";
    s << k8sResources(r);
    s << "          volumeMounts:\n"
      << "            - { name: job, mountPath: " << yamlQuoted(r.jobDir) << " }\n"
      << "      volumes:\n"
      << "        - name: job\n"
      << "          persistentVolumeClaim: { claimName: toyhost-job }  # shared storage holding the job folder\n";
    return s.str();
}

std::string k8sSubmit(const PlanRequest& r) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# Applies the Job (after the checkpoint chain's Job has completed, for a stateful shadertoy).\n"
      << "set -eu\n"
      << "job=" << shellQuoted(r.jobDir) << "\n";
    if (r.stateful) {
        const std::string chain = "job/" + kubernetesJobName("checkpoints", r.jobDir);
        // Whichever comes first: complete, or failed (then no render Job is applied; exit 1).
        // wait -n -p: bash 5.1 or later.
        s << "kubectl apply -f \"$job/checkpoints.yaml\"\n"
          << "kubectl wait --for=condition=complete --timeout=24h " << chain << " >/dev/null &\n"
          << "complete=$!\n"
          << "kubectl wait --for=condition=failed --timeout=24h " << chain << " >/dev/null 2>&1 &\n"
          << "failed=$!\n"
          << "ended='' code=0\n"
          << "wait -n -p ended \"$complete\" \"$failed\" || code=$?\n"
          << "if [ \"$ended\" = \"$failed\" ]; then\n"
          << "  if [ \"$code\" -eq 0 ]; then\n"
          << "    kill \"$complete\" 2>/dev/null || true\n"
          << "    echo \"submit.sh: the checkpoint chain " << chain << " failed (kubectl logs " << chain
          << "): the render Job is not applied\" >&2\n"
          << "    exit 1\n"
          << "  fi\n"
          << "  code=0\n"
          << "  wait \"$complete\" || code=$?\n"
          << "else\n"
          << "  kill \"$failed\" 2>/dev/null || true\n"
          << "fi\n"
          << "if [ \"$code\" -ne 0 ]; then echo \"submit.sh: " << chain << " did not complete within 24 h\" >&2; exit 1; fi\n";
    }
    s << "kubectl apply -f \"$job/job.yaml\"\n";
    return s.str();
}

constexpr int kParallelRetries = 3;  // GNU parallel's count: attempts in all

std::string parallelScript(const PlanRequest& r) {
    std::ostringstream s;
    s << "#!/bin/bash\n"
      << "# Every shard on this machine (or add -S hosts to GNU parallel), written by `toyhost farm plan`.\n"
      << "set -eu\n"
      << "job=" << shellQuoted(r.jobDir) << "\n";
    s << "mkdir -p \"$job/logs\"\n";
    if (r.stateful) s << "\"$job/checkpoints.sh\"\n";
    // -q: GNU parallel runs its command through a shell, which would evaluate a job folder's
    // quotes and $( ) (a folder named "x $(touch PWNED)" ran touch); -q quotes every word of it.
    // -j 1 unless --parallelism: each toyhost on llvmpipe already uses every core. No --halt: a
    // failed shard leaves its siblings running; --retries: a shard that fails is run twice more
    // (resuming from its checkpoint), and parallel's exit status counts the shards failed.
    s << "parallel --will-cite -q --retries " << kParallelRetries << " -j " << (r.parallelism > 0 ? r.parallelism : 1)
      << " --joblog \"$job/logs/parallel.log\" \"$job/run-shard.sh\" {} ::: $(seq 0 " << r.shards - 1 << ")\n";
    return s.str();
}

// Why `value` cannot go into the plan's files, or nothing: a line break or NUL would end the line
// it is written on (a script's, a directive's, farm.json's), and farm.json holds UTF-8 only.
std::optional<std::string> writtenValueProblem(const std::string& value) {
    if (value.find('\n') != std::string::npos) return "holds a line break (newline), which no job file can carry";
    if (value.find('\r') != std::string::npos) return "holds a carriage return, which no job file can carry";
    if (value.find('\0') != std::string::npos) return "holds a NUL byte, which no job file can carry";
    if (!isValidUtf8(value)) return "is not valid UTF-8 (farm.json, which records it, is JSON)";
    return std::nullopt;
}

// The option a run option belongs to: itself ("--fps=30", "--fps"), or the one before it (a value).
std::string runOptionName(const std::vector<std::string>& options, std::size_t i) {
    for (std::size_t j = i + 1; j-- > 0;)
        if (options[j].rfind("-", 0) == 0) return options[j].substr(0, options[j].find('='));
    std::string number = "#";  // appended: GCC 12 warns (-Wrestrict) falsely on "#" + std::string
    number += std::to_string(i + 1);
    return number;
}

// The cluster options a scheduler has no place for: Kubernetes takes --mem and --gres gpu:N as
// resources, GNU parallel none of them.
std::optional<std::string> clusterOptionProblem(const PlanRequest& r) {
    if (r.scheduler == Scheduler::Slurm) return std::nullopt;
    const char* scheduler = r.scheduler == Scheduler::Kubernetes ? "Kubernetes" : "GNU parallel";
    const std::pair<const char*, bool> given[] = {
        {"--partition", !r.partition.empty()}, {"--account", !r.account.empty()}, {"--qos", !r.qos.empty()},
        {"--scheduler-arg", !r.schedulerArgs.empty()}, {"--mem", !r.mem.empty()}, {"--gres", !r.gres.empty()}};
    for (const auto& [name, isGiven] : given) {
        if (!isGiven) continue;
        const std::string option = name;
        if (r.scheduler == Scheduler::Kubernetes && option == "--mem") continue;
        if (r.scheduler == Scheduler::Kubernetes && option == "--gres") {
            if (gresGpus(r.gres)) continue;
            return "--gres " + r.gres + ": Kubernetes takes GPUs only (gpu:N or gpu:TYPE:N, an nvidia.com/gpu limit)";
        }
        return option + ": Slurm's, not " + scheduler + "'s" +
               (r.scheduler == Scheduler::Kubernetes ? " (Kubernetes takes --mem, --gres gpu:N and --cpus-per-task)" : "");
    }
    return std::nullopt;
}

std::optional<std::string> requestProblem(const PlanRequest& r) {
    const std::pair<const char*, const std::string*> values[] = {
        {"--job", &r.jobDir},  {"the target", &r.target}, {"--toyhost", &r.toyhost},
        {"--frame-name", &r.frameName}, {"--time", &r.slurmTime}, {"--image", &r.image},
        {"--partition", &r.partition}, {"--account", &r.account}, {"--qos", &r.qos}, {"--mem", &r.mem}, {"--gres", &r.gres}};
    for (const auto& [name, value] : values)
        if (std::optional<std::string> problem = writtenValueProblem(*value)) return std::string(name) + ": " + *problem;
    for (const std::string& arg : r.schedulerArgs)
        if (std::optional<std::string> problem = writtenValueProblem(arg)) return "--scheduler-arg: " + *problem;
    if (std::optional<std::string> problem = clusterOptionProblem(r)) return problem;
    for (std::size_t i = 0; i < r.runOptions.size(); ++i)
        if (std::optional<std::string> problem = writtenValueProblem(r.runOptions[i]))
            return "run option " + runOptionName(r.runOptions, i) + ": " + *problem;
    // The frames are written by `toyhost run --out JOB/frames/NAME`, whose pattern reads every % (a
    // job folder "100%" failed on every node: "only %d or %0Nd may stand for the frame number"); a
    // % is also the start of Slurm's %A/%a in its log names.
    if (r.jobDir.find('%') != std::string::npos)
        return std::string("--job: holds a %, which toyhost run --out (the frames' path) and Slurm's log names read as a "
                           "placeholder: choose a folder without one");
    if (r.scheduler == Scheduler::Slurm) {
        if (r.jobDir.find('\\') != std::string::npos)
            return std::string("--job: holds a backslash, which turns off the %A/%a names of Slurm's log files (sbatch "
                               "--output): choose a folder without one");
        if (!r.slurmTime.empty())
            if (std::optional<std::string> problem = slurmTimeProblem(r.slurmTime)) return "--time " + r.slurmTime + ": " + *problem;
    }
    if (r.scheduler != Scheduler::Parallel)
        if (std::optional<std::string> problem = slurm::optionsProblem(r)) return problem;
    return std::nullopt;
}

}  // namespace

std::optional<std::string> slurmTimeProblem(const std::string& text) {
    const char* expected = "expected one of Slurm's time formats: MINUTES, MINUTES:SECONDS, HOURS:MINUTES:SECONDS, "
                           "DAYS-HOURS, DAYS-HOURS:MINUTES, DAYS-HOURS:MINUTES:SECONDS (digits only), or UNLIMITED";
    std::string lower;
    for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "unlimited" || lower == "infinite") return std::nullopt;
    // Each field: 1 to 9 digits (Slurm reads them with strtol; more would overflow its minutes).
    auto digits = [](std::string_view field) {
        return !field.empty() && field.size() <= 9 &&
               std::all_of(field.begin(), field.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    // DAYS- takes one to three fields after it (HOURS[:MINUTES[:SECONDS]]), as MINUTES[:SECONDS] or
    // HOURS:MINUTES:SECONDS do without it.
    std::string_view rest = text;
    if (const std::size_t dash = rest.find('-'); dash != std::string_view::npos) {
        if (!digits(rest.substr(0, dash))) return expected;
        rest = rest.substr(dash + 1);
    }
    std::vector<std::string_view> fields;
    for (std::size_t colon; (colon = rest.find(':')) != std::string_view::npos; rest = rest.substr(colon + 1))
        fields.push_back(rest.substr(0, colon));
    fields.push_back(rest);
    if (fields.size() > 3 || !std::all_of(fields.begin(), fields.end(), digits)) return expected;
    return std::nullopt;
}

std::optional<Scheduler> schedulerNamed(const std::string& name) {
    if (name == "slurm") return Scheduler::Slurm;
    if (name == "k8s" || name == "kubernetes") return Scheduler::Kubernetes;
    if (name == "parallel") return Scheduler::Parallel;
    return std::nullopt;
}

std::optional<std::string> frameNameProblem(const std::string& name) {
    // By hand, not std::regex: its matcher recurses once per character and overflows the stack on
    // a long name (a 120,000-character --pattern crashed `farm status`).
    const char* expected = "expected a file name with one frame number placeholder, ending in .png or .exr (f_%06d.png)";
    if (name.size() > 255) return "longer than a file name can be (255 bytes)";
    const std::size_t percent = name.find('%');
    if (percent == std::string::npos || name.find('%', percent + 1) != std::string::npos ||
        name.find('/') != std::string::npos)
        return expected;
    std::size_t at = percent + 1;
    if (at < name.size() && name[at] == '0') {
        const std::size_t width = name.find_first_not_of("0123456789", at + 1);
        if (width == std::string::npos || width == at + 1 || width > at + 3 || name[at + 1] == '0') return expected;
        at = width;
    }
    if (at >= name.size() || name[at] != 'd') return expected;
    const std::string tail = name.substr(at + 1);
    const bool png = tail.size() >= 4 && tail.compare(tail.size() - 4, 4, ".png") == 0;
    const bool exr = tail.size() >= 4 && tail.compare(tail.size() - 4, 4, ".exr") == 0;
    if (!png && !exr) return expected;
    return std::nullopt;
}

std::vector<std::string> planWarnings(const PlanRequest& r) {
    std::vector<std::string> warnings;
    const std::string inside = r.jobDir == "/" ? "/" : r.jobDir + "/";
    if (r.scheduler == Scheduler::Kubernetes && r.target.rfind(inside, 0) != 0)
        warnings.push_back("the target " + r.target + " lies outside the job folder " + r.jobDir +
                           ", the only folder the pods mount: copy it into the job folder, or the image must hold it there");
    return warnings;
}

std::string kubernetesJobName(const std::string& kind, const std::string& jobDir) {
    std::uint32_t hash = 2166136261u;  // FNV-1a
    for (char c : jobDir) hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", hash);
    return "toyhost-" + kind + "-" + hex;
}

std::string redoCommand(Scheduler scheduler, const std::string& jobDir, int index, bool again) {
    const std::string dir = shellQuoted(jobDir);
    const std::string tail = again ? " again" : "";
    switch (scheduler) {
    case Scheduler::Slurm:
        return "sbatch --array=" + std::to_string(index) + " " + dir + "/job.sbatch" + tail;
    case Scheduler::Kubernetes:
        // A finished Job cannot run again: a new one, whose complete shards find their work done.
        return "kubectl delete --ignore-not-found job/" + kubernetesJobName("render", jobDir) + " && kubectl apply -f " +
               dir + "/job.yaml" + (again ? "  # first: rm " + dir + "/checkpoints/shard-" + std::to_string(index) + ".ckpt" : "");
    case Scheduler::Parallel:
        break;
    }
    return dir + "/run-shard.sh " + std::to_string(index) + tail;
}

std::string shellQuoted(const std::string& text) {
    const bool plain = !text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                                "0123456789_-+=./:,@%") == std::string::npos;
    if (plain) return text;
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

Result<std::vector<PlanFile>> planFarm(const PlanRequest& r) {
    if (r.frames < 1) return Error("--frames must be at least 1", Code::Usage);
    std::vector<FrameSpan> spans;
    for (int i = 0; i < std::max(r.shards, 1); ++i) {
        Result<FrameSpan> span = shardSpan(r.frames, r.shards, i);
        if (!span)
            return Error("--shards " + std::to_string(r.shards) + ": expected 1 .. --frames (" + std::to_string(r.frames) + ")",
                         Code::Usage);
        spans.push_back(*span);
    }
    if (r.jobDir.empty() || r.jobDir.front() != '/')
        return Error("the job folder must be an absolute path (every node finds it there): " + r.jobDir, Code::Usage);
    if (std::optional<std::string> problem = frameNameProblem(r.frameName))
        return Error("--frame-name " + r.frameName + ": " + *problem, Code::Usage);
    if (std::optional<std::string> problem = requestProblem(r)) return Error(*problem, Code::Usage);
    if (std::optional<std::string> owned = ownedOption(r.runOptions))
        return Error(*owned + ": farm plan sets it for every shard (from its --frames, --shards, --job and --frame-name)",
                     Code::Usage);

    // One shard has no boundary to checkpoint: the chain is only for stateful runs of several.
    PlanRequest c = r;
    c.stateful = r.stateful && r.shards > 1;
    const std::string dir = shellQuoted(r.jobDir);
    std::vector<PlanFile> files;
    files.push_back({"farm.json", farmJson(r, spans), false});
    files.push_back({"run-shard.sh", runShardScript(c, spans), true});
    if (c.stateful) files.push_back({"checkpoints.sh", chainScript(c, spans), true});
    switch (r.scheduler) {
    case Scheduler::Slurm:
        files.push_back({"job.sbatch", slurm::arrayFile(c), true});
        if (c.stateful) files.push_back({"checkpoints.sbatch", slurm::chainFile(c), true});
        files.push_back({"submit.sh", slurm::submitFile(c), true});
        break;
    case Scheduler::Kubernetes:
        files.push_back({"job.yaml", k8sJob(c, kubernetesJobName("render", r.jobDir), true, "exec " + dir + "/run-shard.sh \"$JOB_COMPLETION_INDEX\""), false});
        if (c.stateful) files.push_back({"checkpoints.yaml", k8sJob(c, kubernetesJobName("checkpoints", r.jobDir), false, "exec " + dir + "/checkpoints.sh"), false});
        files.push_back({"submit.sh", k8sSubmit(c), true});
        break;
    case Scheduler::Parallel:
        files.push_back({"parallel.sh", parallelScript(c), true});
        break;
    }
    return files;
}

}  // namespace toyhost::farm
