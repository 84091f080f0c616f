#include "tiles/tile_status.h"

#include <cstdio>

#include "core/log.h"
#include "core/strings.h"
#include "core/subprocess.h"
#include "tiles/slurm_executor.h"
#include "tiles/task_script.h"
#include "tiles/tile_tasks.h"

namespace cls {
namespace fs = std::filesystem;

bool tiles_finished(const fs::path& tiles_dir, const TilePlan& plan) {
  for (TilePhase phase : kTilePhases)
    if (!pending_tasks(tiles_dir, plan, phase).empty()) return false;
  return true;
}

std::string tiles_progress_line(const fs::path& tiles_dir, const TilePlan& plan) {
  std::string line;
  for (TilePhase phase : kTilePhases) {
    const int total = phase_task_count(plan, phase);
    const int done = total - static_cast<int>(pending_tasks(tiles_dir, plan, phase).size());
    line += cat(line.empty() ? "" : ", ", phase_name(phase), " ", done, "/", total);
  }
  return line;
}

std::string tiles_status_text(const fs::path& tiles_dir) {
  const TilePlan plan = read_tiles_dir(tiles_dir);
  std::string text = cat("tiles: ", tiles_dir.string(), ": ", plan.tiles.size(), " tiles of ", plan.scene.string(), "\n");
  for (TilePhase phase : kTilePhases) {
    const int total = phase_task_count(plan, phase);
    const std::vector<int> pending = pending_tasks(tiles_dir, plan, phase);
    char row[64];
    std::snprintf(row, sizeof row, "  %-12s %d/%d finished", phase_name(phase), total - static_cast<int>(pending.size()), total);
    text += row;
    if (!pending.empty()) {
      std::string names;
      for (int i : pending)
        names += (names.empty() ? "" : ", ") + (phase == TilePhase::Autoencoder ? std::string("shared") : plan.tiles[i].name);
      text += "; not yet: " + names;
    }
    text += "\n";
  }
  const auto jobs = submitted_jobs(tiles_dir);
  if (!jobs.empty()) {
    std::string ids;
    for (const auto& [phase, id] : jobs) ids += cat(ids.empty() ? "" : ", ", phase, " ", id);
    text += "  slurm jobs: " + ids + "\n";
    if (slurm_jobs_active(jobs)) {
      std::string list;
      for (const auto& [phase, id] : jobs) list += (list.empty() ? "" : ",") + id;
      const CommandOutput q = run_capture({"squeue", "--noheader", "--jobs=" + list, "--format=    %i %j %T %r"});
      text += q.out;
    }
  }
  text += "  logs: " + (tiles_dir / "logs").string() + "\n";
  return text;
}

}  // namespace cls
