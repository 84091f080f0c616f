#pragma once
// The one script per phase that both executors run (TILES/jobs/<phase>.sh): it runs
// `citylangsplat tiles task TILES PHASE $SLURM_ARRAY_TASK_ID`, retrying a failed task, so a task runs
// the same way under Slurm (an array task) and locally (the variable set by the local executor).
#include <filesystem>
#include <string>

#include "tiles/tile_tasks.h"

namespace cls {

// Writes TILES/jobs/<phase>.sh (executable) and returns its path. It runs task SLURM_ARRAY_TASK_ID +
// CLS_TASK_OFFSET (0 when unset). `retries`: extra attempts after a failure; a task that was interrupted
// (exit 130: Ctrl-C, scancel's SIGTERM) or killed by a signal is not retried.
std::filesystem::path write_task_script(const std::filesystem::path& tiles_dir, TilePhase phase,
                                        const std::string& binary, int retries);

// TILES/logs/<phase>_<index>.log (Slurm's --output pattern uses %a for the index).
std::filesystem::path task_log(const std::filesystem::path& tiles_dir, TilePhase phase, const std::string& index);

// Single quotes for a POSIX shell.
std::string shell_quote(const std::string& text);

}  // namespace cls
