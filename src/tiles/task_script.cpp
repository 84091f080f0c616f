#include "tiles/task_script.h"

#include "core/atomic_file.h"
#include "core/strings.h"

namespace cls {
namespace fs = std::filesystem;

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

fs::path task_log(const fs::path& tiles_dir, TilePhase phase, const std::string& index) {
  return tiles_dir / "logs" / (std::string(phase_name(phase)) + "_" + index + ".log");
}

fs::path write_task_script(const fs::path& tiles_dir, TilePhase phase, const std::string& binary, int retries) {
  const fs::path script = tiles_dir / "jobs" / (std::string(phase_name(phase)) + ".sh");
  // The task's index: Slurm's array index plus the offset of its chunk (arrays are capped at
  // MaxArraySize, slurm_executor.h); the local executor sets the index alone.
  const std::string command = shell_quote(fs::absolute(binary).string()) + " tiles task " +
                              shell_quote(fs::absolute(tiles_dir).string()) + " " + phase_name(phase) +
                              " \"$((SLURM_ARRAY_TASK_ID + ${CLS_TASK_OFFSET:-0}))\"";
  const std::string text = "#!/usr/bin/env bash\n"
                           "# citylangsplat run-tiles, phase " + std::string(phase_name(phase)) +
                           ": one task (written by run-tiles; rerun run-tiles to change it).\n"
                           "set -u\n"
                           ": \"${SLURM_ARRAY_TASK_ID:?set by sbatch --array or run-tiles --executor local}\"\n"
                           "# LibTorch takes every core of the node unless told: the task's share.\n"
                           "[ -n \"${SLURM_CPUS_PER_TASK:-}\" ] && export OMP_NUM_THREADS=$SLURM_CPUS_PER_TASK\n"
                           "attempts=" + std::to_string(retries + 1) + "\n"
                           "for attempt in $(seq 1 \"$attempts\"); do\n"
                           "  echo \"[$(date -u +%FT%TZ)] $(hostname): attempt $attempt/$attempts\"\n"
                           "  " + command + "\n"
                           "  status=$?\n"
                           "  [ \"$status\" -eq 0 ] && exit 0\n"
                           "  # 130: interrupted after a checkpoint (Ctrl-C, scancel's SIGTERM); above 128: killed. Both\n"
                           "  # end here: the next run-tiles resumes the task.\n"
                           "  [ \"$status\" -ge 128 ] && exit \"$status\"\n"
                           "  echo \"attempt $attempt failed (exit $status)\" >&2\n"
                           "done\n"
                           "exit \"$status\"\n";
  write_text_atomic(script, text);
  fs::permissions(script, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                              fs::perms::others_read | fs::perms::others_exec);
  return script;
}

}  // namespace cls
