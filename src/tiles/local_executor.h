#pragma once
// run-tiles --executor local: the task list on this machine, `jobs` tasks at a time, phase after
// phase (a phase starts when every task of the one before has finished).
#include <filesystem>
#include <string>

#include "tiles/tile_plan.h"

namespace cls {

struct LocalExecutorOptions {
  std::string binary;  // this program (the task scripts run it)
  int jobs = 1;        // tasks at a time
  int retries = 1;
};

// Returns 0 when every task finished, else the first failing task's exit status (its log is named).
int run_tiles_locally(const std::filesystem::path& tiles_dir, const TilePlan& plan, const LocalExecutorOptions& options);

}  // namespace cls
