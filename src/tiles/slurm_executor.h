#pragma once
// run-tiles --executor slurm: sbatch arrays per phase with unfinished tasks, chained by
// --dependency=afterok (a cancelled or failed task cancels what depends on it: --kill-on-invalid-dep),
// logs per task under TILES/logs, job ids in TILES/jobs/submitted.json for `tiles status`. A phase
// with more tasks than the cluster's MaxArraySize goes in several arrays (CLS_TASK_OFFSET each).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tiles/tile_plan.h"

namespace cls {

struct SlurmExecutorOptions {
  std::string binary;
  std::string partition;   // "" = the cluster's default
  int array_limit = 0;     // at most this many tasks of an array at once (%K); 0 = no limit
  int cpus_per_task = 0;   // 0 = the cluster's default
  std::string time_limit;  // sbatch --time, "" = the partition's default
  int retries = 1;
  int max_array_size = 0;  // 0: the cluster's MaxArraySize (scontrol show config), 1001 if unreadable
};

struct SubmittedJob {
  std::string phase, id;
  int offset = 0;     // task index = array index + offset
  std::string array;  // the --array spec
};

// Submits; returns the jobs. Records them in TILES/jobs/submitted.json after each sbatch, so a later
// failure leaves what was queued visible. cls::Error when sbatch is missing or refuses (its message quoted).
std::vector<SubmittedJob> submit_tiles_to_slurm(const std::filesystem::path& tiles_dir, const TilePlan& plan,
                                                const SlurmExecutorOptions& options);

// Slurm's array spec of ascending task indices, runs compressed: {0, 1, 2, 5} -> "0-2,5".
std::string array_spec(const std::vector<int>& tasks);

// What run-tiles last submitted; empty when nothing was.
std::vector<SubmittedJob> submitted_jobs(const std::filesystem::path& tiles_dir);

// squeue's rows ("<id> <name> <state> <reason>") for the jobs still known to it; nullopt when squeue
// failed for another reason than finished jobs (the caller asks again later).
std::optional<std::vector<std::string>> slurm_queue_rows(const std::vector<SubmittedJob>& jobs);

}  // namespace cls
