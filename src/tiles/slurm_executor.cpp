#include "tiles/slurm_executor.h"

#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/strings.h"
#include "core/subprocess.h"
#include "tiles/task_script.h"

namespace cls {
namespace fs = std::filesystem;

std::string array_spec(const std::vector<int>& tasks) {
  std::string spec;
  for (int t : tasks) spec += (spec.empty() ? "" : ",") + std::to_string(t);
  return spec;
}

std::map<std::string, std::string> submit_tiles_to_slurm(const fs::path& tiles_dir, const TilePlan& plan,
                                                         const SlurmExecutorOptions& o) {
  if (!program_exists("sbatch")) throw Error("run-tiles: sbatch not found: run on a Slurm login node, or use --executor local");
  std::map<std::string, std::string> jobs;
  std::string previous;  // the job the next phase waits for
  for (TilePhase phase : kTilePhases) {
    const std::vector<int> pending = pending_tasks(tiles_dir, plan, phase);
    if (pending.empty()) continue;
    const fs::path script = write_task_script(tiles_dir, phase, o.binary, o.retries);
    std::string array = array_spec(pending);
    if (o.array_limit > 0) array += "%" + std::to_string(o.array_limit);
    std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=cls-" + std::string(phase_name(phase)),
                                     "--array=" + array, "--output=" + task_log(tiles_dir, phase, "%a").string(),
                                     "--kill-on-invalid-dep=yes"};
    if (!previous.empty()) argv.push_back("--dependency=afterok:" + previous);
    if (!o.partition.empty()) argv.push_back("--partition=" + o.partition);
    if (o.cpus_per_task > 0) argv.push_back("--cpus-per-task=" + std::to_string(o.cpus_per_task));
    if (!o.time_limit.empty()) argv.push_back("--time=" + o.time_limit);
    argv.push_back(script.string());
    fs::create_directories(tiles_dir / "logs");
    const CommandOutput r = run_capture(argv);
    // --parsable prints "jobid" or "jobid;cluster".
    const std::string id = trim_space(r.out.substr(0, r.out.find(';')));
    if (r.exit_code != 0 || id.empty())
      throw Error(cat("run-tiles: sbatch refused the ", phase_name(phase), " array (exit ", r.exit_code, "): ", r.out));
    log_info(cat("run-tiles: ", phase_name(phase), ": job ", id, " (array ", array, ")",
                 previous.empty() ? std::string() : ", after job " + previous));
    jobs[phase_name(phase)] = id;
    previous = id;
  }
  write_text_atomic(tiles_dir / "jobs" / "submitted.json", nlohmann::json(jobs).dump(2) + "\n");
  return jobs;
}

std::map<std::string, std::string> submitted_jobs(const fs::path& tiles_dir) {
  const fs::path file = tiles_dir / "jobs" / "submitted.json";
  if (!fs::exists(file)) return {};
  try {
    return nlohmann::json::parse(read_text_file(file)).get<std::map<std::string, std::string>>();
  } catch (const nlohmann::json::exception& e) {
    fail(file.string(), std::string("not valid JSON: ") + e.what());
  }
}

bool slurm_jobs_active(const std::map<std::string, std::string>& jobs) {
  if (jobs.empty() || !program_exists("squeue")) return false;
  std::string ids;
  for (const auto& [phase, id] : jobs) ids += (ids.empty() ? "" : ",") + id;
  const CommandOutput r = run_capture({"squeue", "--noheader", "--jobs=" + ids, "--format=%i"});
  return r.exit_code == 0 && !trim_space(r.out).empty();
}

}  // namespace cls
