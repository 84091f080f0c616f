#include "tiles/slurm_executor.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/log.h"
#include "core/strings.h"
#include "core/subprocess.h"
#include "tiles/task_script.h"

namespace cls {
namespace fs = std::filesystem;
using json = nlohmann::json;

std::string array_spec(const std::vector<int>& tasks) {
  std::string spec;
  for (size_t i = 0; i < tasks.size();) {
    size_t j = i;
    while (j + 1 < tasks.size() && tasks[j + 1] == tasks[j] + 1) ++j;
    spec += (spec.empty() ? "" : ",") + std::to_string(tasks[i]) + (j > i ? "-" + std::to_string(tasks[j]) : "");
    i = j + 1;
  }
  return spec;
}

namespace {

int cluster_max_array_size() {
  const CommandOutput r = run_capture({"scontrol", "show", "config"});
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("MaxArraySize", 0) == 0) try {
        return std::stoi(line.substr(line.find('=') + 1));
      } catch (const std::exception&) {
      }
  return 1001;  // Slurm's default
}

void record(const fs::path& tiles_dir, const std::vector<SubmittedJob>& jobs) {
  json j = json::array();
  for (const SubmittedJob& s : jobs) j.push_back({{"phase", s.phase}, {"id", s.id}, {"offset", s.offset}, {"array", s.array}});
  write_text_atomic(tiles_dir / "jobs" / "submitted.json", j.dump(2) + "\n");
}

}  // namespace

std::vector<SubmittedJob> submit_tiles_to_slurm(const fs::path& tiles_dir, const TilePlan& plan,
                                                const SlurmExecutorOptions& o) {
  if (!program_exists("sbatch")) throw Error("run-tiles: sbatch not found: run on a Slurm login node, or use --executor local");
  const int max_array = o.max_array_size > 0 ? o.max_array_size : cluster_max_array_size();
  std::vector<SubmittedJob> jobs;
  std::string previous;  // the jobs the next phase waits for: "id:id:..."
  fs::create_directories(tiles_dir / "logs");
  for (TilePhase phase : kTilePhases) {
    const std::vector<int> pending = pending_tasks(tiles_dir, plan, phase);
    if (pending.empty()) continue;
    const fs::path script = write_task_script(tiles_dir, phase, o.binary, o.retries);
    std::string this_phase;
    // Array indices must stay below MaxArraySize: task t goes to chunk t / max_array, index t % max_array.
    for (size_t first = 0; first < pending.size();) {
      const int offset = pending[first] / max_array * max_array;
      std::vector<int> indices;
      size_t next = first;
      for (; next < pending.size() && pending[next] - offset < max_array; ++next) indices.push_back(pending[next] - offset);
      first = next;
      std::string array = array_spec(indices);
      if (o.array_limit > 0) array += "%" + std::to_string(o.array_limit);
      // %a is the array index: past the first chunk, the log name says the chunk's offset too.
      const fs::path log = task_log(tiles_dir, phase, offset > 0 ? "chunk" + std::to_string(offset) + "+%a" : "%a");
      std::vector<std::string> argv = {"sbatch", "--parsable", "--job-name=cls-" + std::string(phase_name(phase)),
                                       "--array=" + array, "--output=" + log.string(),
                                       "--open-mode=append",  // a rerun's attempt follows the earlier ones
                                       "--kill-on-invalid-dep=yes", "--export=ALL,CLS_TASK_OFFSET=" + std::to_string(offset)};
      if (!previous.empty()) argv.push_back("--dependency=afterok:" + previous);
      if (!o.partition.empty()) argv.push_back("--partition=" + o.partition);
      if (o.cpus_per_task > 0) argv.push_back("--cpus-per-task=" + std::to_string(o.cpus_per_task));
      if (!o.time_limit.empty()) argv.push_back("--time=" + o.time_limit);
      argv.push_back(script.string());
      const CommandOutput r = run_capture(argv);
      // --parsable prints "jobid" or "jobid;cluster".
      const std::string id = trim_space(r.out.substr(0, r.out.find(';')));
      if (r.exit_code != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw Error(cat("run-tiles: sbatch refused the ", phase_name(phase), " array (exit ", r.exit_code, "): ",
                        trim_space(r.err + " " + r.out), jobs.empty() ? "" : "; jobs already queued: see tiles status"));
      log_info(cat("run-tiles: ", phase_name(phase), ": job ", id, " (array ", array, offset > 0 ? cat(", tasks +", offset) : "",
                   ")", previous.empty() ? std::string() : ", after job " + previous));
      jobs.push_back({phase_name(phase), id, offset, array});
      record(tiles_dir, jobs);
      this_phase += (this_phase.empty() ? "" : ":") + id;
    }
    previous = this_phase;
  }
  return jobs;
}

std::vector<SubmittedJob> submitted_jobs(const fs::path& tiles_dir) {
  const fs::path file = tiles_dir / "jobs" / "submitted.json";
  if (!fs::exists(file)) return {};
  std::vector<SubmittedJob> jobs;
  try {
    for (const json& j : json::parse(read_text_file(file)))
      jobs.push_back({j.at("phase").get<std::string>(), j.at("id").get<std::string>(), j.at("offset").get<int>(),
                      j.at("array").get<std::string>()});
  } catch (const json::exception& e) {
    fail(file.string(), std::string("not a valid record of submitted jobs: ") + e.what());
  }
  return jobs;
}

std::optional<std::vector<std::string>> slurm_queue_rows(const std::vector<SubmittedJob>& jobs) {
  if (jobs.empty() || !program_exists("squeue")) return std::vector<std::string>{};
  std::string ids;
  for (const SubmittedJob& j : jobs) ids += (ids.empty() ? "" : ",") + j.id;
  const CommandOutput r = run_capture({"squeue", "--noheader", "--jobs=" + ids, "--format=%i %j %T %r"});
  // squeue refuses ids that have left the queue ("Invalid job id specified"): those jobs are done.
  if (r.exit_code != 0) {
    if (r.err.find("Invalid job id") != std::string::npos) return std::vector<std::string>{};
    return std::nullopt;
  }
  std::vector<std::string> rows;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (!trim_space(line).empty()) rows.push_back(trim_space(line));
  return rows;
}

}  // namespace cls
