// FarmPlan: one render (a shadertoy, its frames, its run options) turned into the files a
// scheduler runs: a Slurm job array, a Kubernetes Indexed Job or a GNU parallel command. Pure text; no GL.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <toyhost/Shards.h>

#include "core/Result.h"

namespace toyhost::farm {

enum class Scheduler { Slurm, Kubernetes, Parallel };

// "slurm", "k8s" (or "kubernetes"), "parallel".
std::optional<Scheduler> schedulerNamed(const std::string& name);

// A shard's frames are toyhost::shardSpan's (toyhost/Shards.h), as `toyhost run --shard i/n` splits.
struct PlanRequest {
    Scheduler scheduler = Scheduler::Parallel;
    std::string toyhost = "toyhost";  // the program as every node finds it
    std::string target;               // the shadertoy as every node finds it
    std::string jobDir;               // absolute, on storage every node shares: frames, checkpoints, logs
    int frames = 0;
    int shards = 0;
    std::string frameName = "f_%06d.png";  // inside jobDir/frames: .png or .exr, numbered by iFrame
    std::vector<std::string> runOptions;   // every other option of the run, passed to each shard once
    // Buffers (or a cubemap pass) carry state from frame to frame: the shards start from a chain of
    // checkpoints made in one sequential pass over the boundaries instead of each simulating its past.
    bool stateful = false;
    std::string slurmTime;   // sbatch --time; empty: the partition's limit
    int cpusPerTask = 0;     // sbatch --cpus-per-task, Kubernetes cpu request; 0: not given
    int parallelism = 0;     // shards at once (GNU parallel -j, Job parallelism, array %); 0: all
    std::string image = "toyhost:latest";  // the container image of the Kubernetes Job
    // A cluster's own: Slurm's --partition, --account, --qos, --mem, --gres as #SBATCH lines of
    // every job file (Kubernetes: --mem and --gres gpu:N become requests and limits; the others are
    // refused there, as all are for GNU parallel); schedulerArgs: any further sbatch option, one
    // word each (--constraint=avx2).
    std::string partition, account, qos, mem, gres;
    std::vector<std::string> schedulerArgs;
};

struct PlanFile {
    std::string name;  // relative to jobDir
    std::string text;
    bool executable = false;
};

// Every value written into the files (paths, --time, run options) is refused when it holds a line
// break, a carriage return or NUL, or is not UTF-8; paths are quoted for the shell and, in #SBATCH
// lines, for sbatch's own directive parser.
// The files of the job, the run options appearing once (in run-shard.sh, which every scheduler's
// file calls): farm.json (what `farm status` and `farm join` read), run-shard.sh, checkpoints.sh
// for a stateful shadertoy, and the scheduler's own: job.sbatch (+ checkpoints.sbatch) and
// submit.sh; job.yaml (+ checkpoints.yaml) and submit.sh; or parallel.sh.
Result<std::vector<PlanFile>> planFarm(const PlanRequest& request);

// Why `name` cannot be the frames' file name, or nothing: one %d or %0Nd, no other %, no folder,
// .png or .exr (what `toyhost run --out` numbers by iFrame).
std::optional<std::string> frameNameProblem(const std::string& name);

// Why `text` is not a time limit sbatch --time takes, or nothing: MINUTES, MINUTES:SECONDS,
// HOURS:MINUTES:SECONDS, DAYS-HOURS, DAYS-HOURS:MINUTES, DAYS-HOURS:MINUTES:SECONDS, UNLIMITED.
std::optional<std::string> slurmTimeProblem(const std::string& text);

// What the plan should tell its user without refusing it: a Kubernetes target outside the job
// folder (the pods mount only the job folder).
std::vector<std::string> planWarnings(const PlanRequest& request);

// The Kubernetes Jobs' names of the job folder `jobDir`: "toyhost-render-HASH" and
// "toyhost-checkpoints-HASH", HASH 8 hex digits of the folder's path (two plans never collide).
std::string kubernetesJobName(const std::string& kind, const std::string& jobDir);

// The command that renders shard `index` of the plan in `jobDir` again, as its scheduler runs it:
// sbatch --array=INDEX, run-shard.sh INDEX, or a Kubernetes Job re-applied. `again`: the shard's
// frames are rendered anew (its checkpoint removed), else it resumes from its checkpoint.
std::string redoCommand(Scheduler scheduler, const std::string& jobDir, int index, bool again);

// `text` as one word for sh/bash: unchanged when it is plain, else in single quotes.
std::string shellQuoted(const std::string& text);

}  // namespace toyhost::farm
