#include "tiles/tile_status.h"

#include <cstdio>

#include "core/log.h"
#include "core/strings.h"
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
  const std::vector<SubmittedJob> jobs = submitted_jobs(tiles_dir);
  if (!jobs.empty()) {
    std::string ids;
    for (const SubmittedJob& j : jobs) ids += cat(ids.empty() ? "" : ", ", j.phase, " ", j.id, " (array ", j.array, ")");
    text += "  slurm jobs: " + ids + "\n";
    const auto rows = slurm_queue_rows(jobs);
    if (!rows) text += "  squeue did not answer: try again\n";
    for (const std::string& row : rows.value_or(std::vector<std::string>{})) text += "    " + row + "\n";
  }
  text += "  logs: " + (tiles_dir / "logs").string() + "\n";
  return text;
}

}  // namespace cls
