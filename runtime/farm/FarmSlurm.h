// FarmSlurm: the Slurm files of a plan (job.sbatch, checkpoints.sbatch, submit.sh) and the checks
// of the cluster options written into them. Internal to farm/FarmPlan.cpp; pure text.
#pragma once

#include <optional>
#include <string>

#include "farm/FarmPlan.h"

namespace toyhost::farm::slurm {

// A value of an #SBATCH line as sbatch's directive parser reads it back.
std::string directiveWord(const std::string& text);

// Seconds of a time limit in one of sbatch --time's formats (slurmTimeProblem's); nullopt for
// UNLIMITED (or a text that is not one).
std::optional<long long> seconds(const std::string& text);

// The checkpoint chain's --time: (K-1) times a shard's, as it simulates the frames of K-1 shards
// (docs/farm.md); empty when the shards have no limit of their own.
std::string chainTime(const PlanRequest& request);

// N of --signal=B:TERM@N: how long before its limit a task is told to stop (docs/farm.md).
int signalLead(const PlanRequest& request);

// Why the cluster options cannot be written for Slurm (a --mem sbatch does not take, a
// --scheduler-arg that is not an option or one the plan sets itself), or nothing.
std::optional<std::string> optionsProblem(const PlanRequest& request);

std::string arrayFile(const PlanRequest& request);   // job.sbatch
std::string chainFile(const PlanRequest& request);   // checkpoints.sbatch
std::string submitFile(const PlanRequest& request);  // submit.sh

}  // namespace toyhost::farm::slurm
