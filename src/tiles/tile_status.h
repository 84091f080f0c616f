#pragma once
// Progress of run-tiles (`citylangsplat tiles status`): tasks finished per phase, the tiles still
// missing, and what Slurm says of the jobs run-tiles submitted.
#include <filesystem>
#include <string>

#include "tiles/tile_plan.h"

namespace cls {

std::string tiles_status_text(const std::filesystem::path& tiles_dir);
// Every task of every phase finished.
bool tiles_finished(const std::filesystem::path& tiles_dir, const TilePlan& plan);
// "features 4/4, autoencoder 0/1, train 0/4": one line for progress while waiting.
std::string tiles_progress_line(const std::filesystem::path& tiles_dir, const TilePlan& plan);

}  // namespace cls
