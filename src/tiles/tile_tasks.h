#pragma once
// The task list of run-tiles (docs/scale.md): three phases, each a set of independent tasks that any
// executor (local processes or a Slurm array) runs as `citylangsplat tiles task TILES PHASE INDEX`:
//   features     one task per tile: label maps and features (`run --stop-after features`)
//   autoencoder  one task: the autoencoder shared by all tiles, on SAM features sampled from every tile
//   train        one task per tile: the rest of `run` with the shared autoencoder
// A task that finished leaves TILES/status/<phase>_<index>.json with the fingerprint of the plan and
// the settings it ran under, so a rerun submits only the missing ones (a marker of another plan or other
// settings, even one written late by a job still running then, does not count); within a task the
// pipeline's stage stamps resume what was half done.
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/pipeline_config.h"
#include "tiles/tile_plan.h"

namespace cls {

enum class TilePhase { Features, Autoencoder, Train };
constexpr TilePhase kTilePhases[] = {TilePhase::Features, TilePhase::Autoencoder, TilePhase::Train};
const char* phase_name(TilePhase phase);
TilePhase parse_tile_phase(const std::string& name);  // cls::UsageError for an unknown phase

// What every tile shares (TILES/run-tiles.json): the `run` options that are not per scene
// (pipeline_options() without per_scene(): `run-tiles` takes them as `run` does), and the shared
// autoencoder's sample. run-tiles resolves `--models auto` and the default counts once, where it is
// started, so every task of every node runs the same models and schedule.
// run's defaults but the baseline: the one on the shared autoencoder (langsplat-original trains its own
// per scene, the tiles share one).
inline PipelineConfig tile_pipeline_defaults() {
  PipelineConfig c;
  c.baselines = {"langsplat"};
  return c;
}

struct RunTilesSettings {
  PipelineConfig pipeline = tile_pipeline_defaults();
  int64_t autoencoder_samples = 200000;  // SAM features the shared autoencoder trains on, drawn from all tiles

  nlohmann::json to_json() const;
  static RunTilesSettings from_json(const nlohmann::json& j, const std::string& file);
};
// The options run-tiles carries to every tile.
bool is_shared_by_tiles(const OptionList<PipelineConfig>::Binding& binding);

// Writes the settings (atomic); returns whether they differ from those recorded (every task then runs
// again: the stage stamps still reuse whatever the change leaves valid).
bool write_run_settings(const std::filesystem::path& tiles_dir, const RunTilesSettings& settings);
RunTilesSettings read_run_settings(const std::filesystem::path& tiles_dir);

int phase_task_count(const TilePlan& plan, TilePhase phase);
std::filesystem::path task_marker(const std::filesystem::path& tiles_dir, TilePhase phase, int index);
// Of tiles.json and run-tiles.json as they are now: what a marker must hold to count.
std::string tasks_fingerprint(const std::filesystem::path& tiles_dir);
// The tasks of a phase without a marker of the current fingerprint.
std::vector<int> pending_tasks(const std::filesystem::path& tiles_dir, const TilePlan& plan, TilePhase phase);

std::filesystem::path tile_run_dir(const std::filesystem::path& tiles_dir, const Tile& tile);  // TILES/<tile>/citylangsplat
std::filesystem::path shared_autoencoder(const std::filesystem::path& tiles_dir);           // TILES/autoencoder.safetensors

// `auto` and zero counts replaced by what they stand for (the models found from here, their schedule);
// the settings checked as `run` checks them. cls::Error with the reason when --models clip finds no weights.
RunTilesSettings resolve_run_settings(const std::filesystem::path& tiles_dir, const TilePlan& plan,
                                      RunTilesSettings settings);

// The pipeline configuration of one tile in a phase.
PipelineConfig tile_pipeline_config(const std::filesystem::path& tiles_dir, const Tile& tile,
                                    const RunTilesSettings& settings, TilePhase phase);

// Runs one task in this process; writes its marker when it finished. Returns the exit status
// (core/exit_codes.h; 130 when interrupted).
int run_tile_task(const std::filesystem::path& tiles_dir, TilePhase phase, int index);

}  // namespace cls
