#include "tiles/local_executor.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <map>

#include "core/cpu_threads.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "core/progress.h"
#include "core/subprocess.h"
#include "tiles/task_script.h"

namespace cls {
namespace fs = std::filesystem;

namespace {

// One local run-tiles per tiles directory at a time (two would train a tile twice into one folder).
class TilesLock {
 public:
  explicit TilesLock(const fs::path& tiles_dir) : path_(tiles_dir / ".run-tiles.lock") {
    fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) fail(path_.string(), "cannot create the lock file");
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      close(fd_);
      fail(path_.string(), "another run-tiles is running on these tiles: wait for it to finish");
    }
  }
  ~TilesLock() { close(fd_); }  // closing releases the lock
  TilesLock(const TilesLock&) = delete;
  TilesLock& operator=(const TilesLock&) = delete;

 private:
  fs::path path_;
  int fd_ = -1;
};

}  // namespace

int run_tiles_locally(const fs::path& tiles_dir, const TilePlan& plan, const LocalExecutorOptions& o) {
  const TilesLock lock(tiles_dir);
  install_interrupt_handlers();  // Ctrl-C or a kill of run-tiles stops the tasks after their checkpoint
  // The cores shared among the tasks (LibTorch and OpenMP would each take all of them).
  const int cores = default_cpu_threads();  // --threads N or OMP_NUM_THREADS where given
  const std::string threads = "OMP_NUM_THREADS=" + std::to_string(std::max(1, cores / o.jobs));
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
    bool forwarded = false;
    while (next < pending.size() || !running.empty()) {
      while (failure == 0 && !interrupt_requested() && next < pending.size() && static_cast<int>(running.size()) < o.jobs) {
        const int index = pending[next++];
        const fs::path log = task_log(tiles_dir, phase, std::to_string(index));
        running[spawn_logged({"bash", script.string()}, log, {"SLURM_ARRAY_TASK_ID=" + std::to_string(index), threads})] =
            index;
      }
      if (running.empty()) break;
      if (interrupt_requested() && !forwarded) {
        for (const auto& [pid, index] : running) kill(-pid, SIGTERM);  // the task's process group
        forwarded = true;
      }
      int code = 0;
      const pid_t pid = wait_any_child(code, 0.5);
      if (pid < 0) throw Error("run-tiles: lost track of the running tasks (waitpid: no child)");
      const auto it = running.find(pid);
      if (it == running.end()) continue;  // 0: none ended yet
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
    if (interrupt_requested()) return kInterruptedExit;
    if (failure != 0) return failure;
  }
  return 0;
}

}  // namespace cls
