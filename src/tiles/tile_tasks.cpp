#include "tiles/tile_tasks.h"

#include <chrono>
#include <unistd.h>

#include "citymodel/city_model.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/hash.h"
#include "core/log.h"
#include "core/run_layout.h"
#include "language/autoencoder_stage.h"
#include "pipeline/feature_source.h"
#include "pipeline/pipeline.h"

namespace cls {
namespace fs = std::filesystem;
using json = nlohmann::json;

const char* phase_name(TilePhase phase) {
  switch (phase) {
    case TilePhase::Features: return "features";
    case TilePhase::Autoencoder: return "autoencoder";
    case TilePhase::Train: return "train";
  }
  return "?";
}

TilePhase parse_tile_phase(const std::string& name) {
  for (TilePhase p : kTilePhases)
    if (name == phase_name(p)) return p;
  throw UsageError("tiles: unknown phase '" + name + "' (features, autoencoder or train)");
}

bool is_shared_by_tiles(const OptionList<PipelineConfig>::Binding& binding) { return !binding.per_scene; }

json RunTilesSettings::to_json() const {
  return {{"pipeline", pipeline_options().to_json(pipeline, is_shared_by_tiles)},
          {"autoencoder_samples", autoencoder_samples}};
}

RunTilesSettings RunTilesSettings::from_json(const json& j, const std::string& file) {
  RunTilesSettings s;
  if (!j.is_object() || !j.contains("pipeline")) fail(file, "not valid run-tiles settings: no \"pipeline\"");
  pipeline_options().from_json(j.at("pipeline"), s.pipeline, file);
  try {
    s.autoencoder_samples = j.at("autoencoder_samples").get<int64_t>();
  } catch (const json::exception& e) {
    fail(file, std::string("not valid run-tiles settings: ") + e.what());
  }
  return s;
}

namespace {
fs::path settings_file(const fs::path& tiles_dir) { return tiles_dir / "run-tiles.json"; }
}  // namespace

bool write_run_settings(const fs::path& tiles_dir, const RunTilesSettings& settings) {
  const fs::path file = settings_file(tiles_dir);
  const std::string text = settings.to_json().dump(2) + "\n";
  if (fs::exists(file) && read_text_file(file) == text) return false;
  write_text_atomic(file, text);
  return true;
}

RunTilesSettings read_run_settings(const fs::path& tiles_dir) {
  const fs::path file = settings_file(tiles_dir);
  if (!fs::exists(file)) fail(file.string(), "missing: start the tiles with `citylangsplat run-tiles` first");
  try {
    return RunTilesSettings::from_json(json::parse(read_text_file(file)), file.string());
  } catch (const json::exception& e) {
    fail(file.string(), std::string("not valid JSON: ") + e.what());
  }
}

int phase_task_count(const TilePlan& plan, TilePhase phase) {
  return phase == TilePhase::Autoencoder ? 1 : static_cast<int>(plan.tiles.size());
}

fs::path task_marker(const fs::path& tiles_dir, TilePhase phase, int index) {
  return tiles_dir / "status" / (std::string(phase_name(phase)) + "_" + std::to_string(index) + ".json");
}

std::string tasks_fingerprint(const fs::path& tiles_dir) {
  const fs::path settings = settings_file(tiles_dir);
  return fnv1a64_hex(read_text_file(tiles_dir / "tiles.json") + "|" +
                     (fs::exists(settings) ? read_text_file(settings) : std::string()));
}

std::vector<int> pending_tasks(const fs::path& tiles_dir, const TilePlan& plan, TilePhase phase) {
  const std::string fingerprint = tasks_fingerprint(tiles_dir);
  std::vector<int> pending;
  for (int i = 0; i < phase_task_count(plan, phase); ++i) {
    const fs::path marker = task_marker(tiles_dir, phase, i);
    bool current = false;
    if (fs::exists(marker)) try {
        current = json::parse(read_text_file(marker)).value("fingerprint", "") == fingerprint;
      } catch (const json::exception&) {  // a torn or foreign file: the task runs again
      }
    if (!current) pending.push_back(i);
  }
  return pending;
}

fs::path tile_run_dir(const fs::path& tiles_dir, const Tile& tile) { return RunLayout::of_scene(tiles_dir / tile.name).root(); }
fs::path shared_autoencoder(const fs::path& tiles_dir) { return tiles_dir / "autoencoder.safetensors"; }

RunTilesSettings resolve_run_settings(const fs::path& tiles_dir, const TilePlan& plan, RunTilesSettings s) {
  const PipelineConfig probe = tile_pipeline_config(tiles_dir, plan.tiles.front(), s, TilePhase::Features);
  probe.validate();
  const FeatureSource source = resolve_feature_source(probe, load_taxonomy(probe.city_options));
  if (!source.provider) throw Error("run-tiles: " + source.missing_weights);
  if (!source.note.empty()) log_warn("run-tiles: " + source.note);
  s.pipeline.features.models = source.models;
  s.pipeline.rgb_iterations = source.schedule.rgb_iterations;
  s.pipeline.language_iterations = source.schedule.language_iterations;
  s.pipeline.autoencoder_epochs = source.schedule.autoencoder_epochs;
  return s;
}

PipelineConfig tile_pipeline_config(const fs::path& tiles_dir, const Tile& tile, const RunTilesSettings& s,
                                    TilePhase phase) {
  PipelineConfig c = s.pipeline;
  c.scene_dir = tiles_dir / tile.name;
  c.out_dir = tile_run_dir(tiles_dir, tile);
  read_scene_config(SceneFiles{c.scene_dir}.config(), c);
  if (c.field != "sparse") c.autoencoder = shared_autoencoder(tiles_dir).string();  // the sparse field has none
  c.stop_after = phase == TilePhase::Features ? "features" : "none";
  return c;
}

namespace {

void run_shared_autoencoder(const fs::path& tiles_dir, const TilePlan& plan, const RunTilesSettings& s) {
  AutoencoderStageOptions o;
  for (const Tile& t : plan.tiles) o.features_dirs.push_back(RunLayout(tile_run_dir(tiles_dir, t)).features());
  o.out = shared_autoencoder(tiles_dir);
  o.max_samples = s.autoencoder_samples;
  o.train.epochs = s.pipeline.autoencoder_epochs;  // resolved by run-tiles
  const AutoencoderReport r = run_autoencoder_stage(o);
  log_info(cat("tiles: shared autoencoder: ", r.train_samples, " SAM features from ", plan.tiles.size(),
               " tiles, held-out cosine ", r.holdout_cosine));
}

}  // namespace

int run_tile_task(const fs::path& tiles_dir, TilePhase phase, int index) {
  const TilePlan plan = read_tiles_dir(tiles_dir);
  const RunTilesSettings settings = read_run_settings(tiles_dir);
  if (index < 0 || index >= phase_task_count(plan, phase))
    throw UsageError(cat("tiles task: ", phase_name(phase), " has tasks 0..", phase_task_count(plan, phase) - 1,
                         ", not ", index));
  const std::string fingerprint = tasks_fingerprint(tiles_dir);  // what this task runs under
  const auto start = std::chrono::steady_clock::now();
  if (phase == TilePhase::Autoencoder) {
    if (settings.pipeline.field == "sparse")
      log_info("tiles: the sparse language field decodes nothing: no shared autoencoder to train");
    else
      run_shared_autoencoder(tiles_dir, plan, settings);  // throws on failure
  } else {
    const Tile& tile = plan.tiles[index];
    log_info(cat("tiles: ", phase_name(phase), " of ", tile.name, " (", tile.images.size(), " images)"));
    const int code = exit_code(run_pipeline(tile_pipeline_config(tiles_dir, tile, settings, phase)).outcome);
    if (code != kExitOk) return code;
  }
  char host[256] = "";
  gethostname(host, sizeof host - 1);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_text_atomic(task_marker(tiles_dir, phase, index),
                    json({{"phase", phase_name(phase)}, {"index", index}, {"seconds", seconds}, {"host", host},
                          {"fingerprint", fingerprint}}).dump() + "\n");
  return kExitOk;
}

}  // namespace cls
