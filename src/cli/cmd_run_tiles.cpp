// citylangsplat run-tiles: every tile's pipeline, with one shared autoencoder, on Slurm or locally
// (src/tiles/tile_tasks.h has the task list).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli/commands.h"
#include "core/args.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/log.h"
#include "pipeline/pipeline_config.h"
#include "tiles/local_executor.h"
#include "tiles/slurm_executor.h"
#include "tiles/tile_status.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_run_tiles(int argc, char** argv) {
  Args args("run-tiles",
            "Run the pipeline on every tile of a `tile` directory: features per tile, then ONE autoencoder on "
            "SAM features sampled from all tiles (latents of different tiles must mean the same to be merged), "
            "then photometric and language training per tile. --executor slurm submits an sbatch array per "
            "phase (several past the cluster's MaxArraySize), chained with afterok dependencies, and returns "
            "(add --wait to wait); --executor local runs the same tasks here, --jobs at a time. A rerun submits only the tasks that have not finished "
            "(TILES/status); `citylangsplat tiles status TILES` shows progress, TILES/logs has a log per task. "
            "The options after --wait are `run`'s, for every tile.");
  fs::path tiles_arg;
  std::string executor = "local";
  LocalExecutorOptions local;
  SlurmExecutorOptions slurm;
  int retries = 1;
  bool wait = false;
  RunTilesSettings s;
  args.positional("TILES", tiles_arg, "tiles directory (`citylangsplat tile --out`)")
      .bind("executor", executor, "local or slurm", choice_codec({"local", "slurm"}))
      .bind("jobs", local.jobs, "local: tasks at a time")
      .bind("partition", slurm.partition, "slurm: partition (default: the cluster's)")
      .bind("array-limit", slurm.array_limit, "slurm: at most this many tasks of an array at once (0: no limit)")
      .bind("cpus-per-task", slurm.cpus_per_task, "slurm: CPUs per task (0: the cluster's default)")
      .bind("time", slurm.time_limit, "slurm: time limit per task (sbatch --time)")
      .bind("retries", retries, "attempts after a failed task (an interrupted or cancelled one is not retried)")
      .flag("wait", wait, "slurm: wait until the submitted jobs have left the queue, then report")
      .bind("autoencoder-samples", s.autoencoder_samples,
            "SAM features the shared autoencoder trains on, drawn at random from all tiles");
  pipeline_options().declare(args, s.pipeline, is_shared_by_tiles);
  if (!args.parse(argc, argv)) return kExitOk;
  pipeline_options().apply(args, s.pipeline, is_shared_by_tiles);
  const fs::path tiles_dir = fs::absolute(tiles_arg);
  const TilePlan plan = read_tiles_dir(tiles_dir);
  if (s.autoencoder_samples < 1) throw UsageError("run-tiles: --autoencoder-samples must be >= 1");
  if (retries < 0) throw UsageError("run-tiles: --retries must be >= 0");
  const std::vector<SubmittedJob> earlier = submitted_jobs(tiles_dir);
  const auto queued = slurm_queue_rows(earlier);
  if (!queued || !queued->empty())
    throw UsageError("run-tiles: jobs of the last submission are still queued or running (citylangsplat tiles status " +
                     tiles_dir.string() + "): wait for them, or scancel them, then run again");
  s = resolve_run_settings(tiles_dir, plan, s);
  if (write_run_settings(tiles_dir, s)) log_info("run-tiles: new settings: every task runs (finished stages are reused)");
  const std::string binary = fs::read_symlink("/proc/self/exe").string();

  if (executor == "local") {
    local.binary = binary;
    local.retries = retries;
    if (local.jobs < 1) throw UsageError("run-tiles: --jobs must be >= 1");
    const int code = run_tiles_locally(tiles_dir, plan, local);
    std::printf("%s", tiles_status_text(tiles_dir).c_str());
    return code == 0 ? kExitOk : kExitError;
  }
  slurm.binary = binary;
  slurm.retries = retries;
  const std::vector<SubmittedJob> jobs = submit_tiles_to_slurm(tiles_dir, plan, slurm);
  if (jobs.empty()) std::printf("run-tiles: every task has finished; nothing submitted\n");
  if (!wait) {
    std::printf("Submitted; follow with: citylangsplat tiles status %s\n", tiles_dir.string().c_str());
    return kExitOk;
  }
  std::string last;
  for (;;) {
    const auto rows = slurm_queue_rows(jobs);  // nullopt: squeue did not answer this time
    if (rows && rows->empty()) break;
    const std::string line = tiles_progress_line(tiles_dir, plan);
    if (line != last) log_info("run-tiles: finished tasks: " + line);
    last = line;
    std::this_thread::sleep_for(std::chrono::seconds(3));
  }
  const std::string status = tiles_status_text(tiles_dir);
  std::printf("%s", status.c_str());
  return tiles_finished(tiles_dir, plan) ? kExitOk : kExitError;
}

}  // namespace cls
