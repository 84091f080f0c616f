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
#include "tiles/local_executor.h"
#include "tiles/slurm_executor.h"
#include "tiles/tile_status.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace fs = std::filesystem;

int cmd_run_tiles(int argc, char** argv) {
  const RunTilesSettings d;
  Args args("run-tiles",
            "Run the pipeline on every tile of a `tile` directory: features per tile, then ONE autoencoder on "
            "SAM features sampled from all tiles (latents of different tiles must mean the same to be merged), "
            "then photometric and language training per tile. --executor slurm submits an sbatch array per "
            "phase (several past the cluster's MaxArraySize), chained with afterok dependencies, and returns "
            "(add --wait to wait); --executor local runs the same tasks here, --jobs at a time. A rerun submits only the tasks that have not finished "
            "(TILES/status); `citylangsplat tiles status TILES` shows progress, TILES/logs has a log per task.");
  args.positional("TILES", "tiles directory (`citylangsplat tile --out`)")
      .option("executor", "local", "local or slurm")
      .option("jobs", "1", "local: tasks at a time")
      .option("partition", "", "slurm: partition (default: the cluster's)")
      .option("array-limit", "0", "slurm: at most this many tasks of an array at once (0: no limit)")
      .option("cpus-per-task", "0", "slurm: CPUs per task (0: the cluster's default)")
      .option("time", "", "slurm: time limit per task (sbatch --time)")
      .option("retries", "1", "attempts after a failed task (an interrupted or cancelled one is not retried)")
      .flag("wait", "slurm: wait until the submitted jobs have left the queue, then report")
      .option("models", d.models, "as run --models: auto, real, tiny or synthetic")
      .option("resolution", "1", "as run --resolution", "r")
      .option("rgb-iterations", "0", "as run (0: the models' default)")
      .option("language-iterations", "0", "as run (0: the models' default)")
      .option("autoencoder-epochs", "0", "as run (0: the models' default)")
      .option("autoencoder-samples", std::to_string(d.autoencoder_samples),
              "SAM features the shared autoencoder trains on, drawn at random from all tiles")
      .flag("no-baseline", "do not train the LangSplat baseline");
  if (!args.parse(argc, argv)) return kExitOk;
  const fs::path tiles_dir = fs::absolute(args.get("TILES"));
  const TilePlan plan = read_tiles_dir(tiles_dir);

  RunTilesSettings s;
  s.models = args.get("models");
  s.resolution = static_cast<int>(args.get_int("resolution"));
  s.rgb_iterations = static_cast<int>(args.get_int("rgb-iterations"));
  s.language_iterations = static_cast<int>(args.get_int("language-iterations"));
  s.autoencoder_epochs = static_cast<int>(args.get_int("autoencoder-epochs"));
  s.autoencoder_samples = args.get_int("autoencoder-samples");
  s.baseline = !args.flag_set("no-baseline");
  if (s.rgb_iterations < 0 || s.language_iterations < 0 || s.autoencoder_epochs < 0 || s.autoencoder_samples < 1)
    throw UsageError("run-tiles: counts must not be negative (and --autoencoder-samples >= 1)");
  const int retries = static_cast<int>(args.get_int("retries"));
  if (retries < 0) throw UsageError("run-tiles: --retries must be >= 0");
  const std::vector<SubmittedJob> earlier = submitted_jobs(tiles_dir);
  const auto queued = slurm_queue_rows(earlier);
  if (!queued || !queued->empty())
    throw UsageError("run-tiles: jobs of the last submission are still queued or running (citylangsplat tiles status " +
                     tiles_dir.string() + "): wait for them, or scancel them, then run again");
  s = resolve_run_settings(tiles_dir, plan, s);
  if (write_run_settings(tiles_dir, s)) log_info("run-tiles: new settings: every task runs (finished stages are reused)");
  const std::string binary = fs::read_symlink("/proc/self/exe").string();

  const std::string executor = args.get("executor");
  if (executor == "local") {
    LocalExecutorOptions o;
    o.binary = binary;
    o.jobs = static_cast<int>(args.get_int("jobs"));
    o.retries = retries;
    if (o.jobs < 1) throw UsageError("run-tiles: --jobs must be >= 1");
    const int code = run_tiles_locally(tiles_dir, plan, o);
    std::printf("%s", tiles_status_text(tiles_dir).c_str());
    return code == 0 ? kExitOk : kExitError;
  }
  if (executor != "slurm") throw UsageError("run-tiles: --executor must be local or slurm, not '" + executor + "'");
  SlurmExecutorOptions o;
  o.binary = binary;
  o.partition = args.get("partition");
  o.array_limit = static_cast<int>(args.get_int("array-limit"));
  o.cpus_per_task = static_cast<int>(args.get_int("cpus-per-task"));
  o.time_limit = args.get("time");
  o.retries = retries;
  const std::vector<SubmittedJob> jobs = submit_tiles_to_slurm(tiles_dir, plan, o);
  if (jobs.empty()) std::printf("run-tiles: every task has finished; nothing submitted\n");
  if (!args.flag_set("wait")) {
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
