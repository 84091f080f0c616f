#include "tiles/local_executor.h"

#include <map>

#include "core/log.h"
#include "core/progress.h"
#include "core/subprocess.h"
#include "tiles/task_script.h"

namespace cls {
namespace fs = std::filesystem;

int run_tiles_locally(const fs::path& tiles_dir, const TilePlan& plan, const LocalExecutorOptions& o) {
  for (TilePhase phase : kTilePhases) {
    const std::vector<int> pending = pending_tasks(tiles_dir, plan, phase);
    if (pending.empty()) {
      log_info(cat("run-tiles: ", phase_name(phase), ": every task already finished"));
      continue;
    }
    const fs::path script = write_task_script(tiles_dir, phase, o.binary, o.retries);
    Progress progress(cat("run-tiles: ", phase_name(phase)), pending.size(), "tasks");
    std::map<pid_t, int> running;  // pid -> task index
    size_t next = 0;
    int failure = 0;
    while (next < pending.size() || !running.empty()) {
      while (failure == 0 && next < pending.size() && static_cast<int>(running.size()) < o.jobs) {
        const int index = pending[next++];
        const fs::path log = task_log(tiles_dir, phase, std::to_string(index));
        running[spawn_logged({"bash", script.string()}, log, {"SLURM_ARRAY_TASK_ID=" + std::to_string(index)})] = index;
      }
      if (running.empty()) break;
      int code = 0;
      const pid_t pid = wait_any_child(code);
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const int index = it->second;
      running.erase(it);
      progress.advance();
      if (code != 0) {
        log_warn(cat("run-tiles: ", phase_name(phase), " task ", index, " failed (exit ", code, "); see ",
                      task_log(tiles_dir, phase, std::to_string(index)).string()));
        if (failure == 0) failure = code;  // let the running tasks finish, start no more
      }
    }
    progress.finish();
    if (failure != 0) return failure;
  }
  return 0;
}

}  // namespace cls
