#pragma once
// run-tiles --executor slurm: one sbatch array per phase with unfinished tasks, chained by
// --dependency=afterok (a cancelled or failed task cancels what depends on it: --kill-on-invalid-dep),
// logs per task under TILES/logs, job ids in TILES/jobs/submitted.json for `tiles status`.
#include <filesystem>
#include <map>
#include <string>

#include "tiles/tile_plan.h"

namespace cls {

struct SlurmExecutorOptions {
  std::string binary;
  std::string partition;   // "" = the cluster's default
  int array_limit = 0;     // at most this many tasks of an array at once (%K); 0 = no limit
  int cpus_per_task = 0;   // 0 = the cluster's default
  std::string time_limit;  // sbatch --time, "" = the partition's default
  int retries = 1;
};

// Submits; returns phase -> job id. cls::Error when sbatch is missing or refuses (its message quoted).
std::map<std::string, std::string> submit_tiles_to_slurm(const std::filesystem::path& tiles_dir, const TilePlan& plan,
                                                         const SlurmExecutorOptions& options);

// Slurm's "1,3,4": the array indices of `tasks`.
std::string array_spec(const std::vector<int>& tasks);

// The ids run-tiles last submitted (phase -> job id); empty when none were.
std::map<std::string, std::string> submitted_jobs(const std::filesystem::path& tiles_dir);

// Whether any of `jobs` is still known to squeue (pending or running). False without squeue.
bool slurm_jobs_active(const std::map<std::string, std::string>& jobs);

}  // namespace cls
