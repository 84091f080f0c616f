#include "pipeline/run_context.h"

#include <algorithm>
#include <stdexcept>

#include "core/error.h"
#include "core/log.h"
#include "raycast/label_export.h"
#include "scene/image_loader.h"

namespace cls {
namespace fs = std::filesystem;

std::vector<std::string> RunContext::methods() const {
  std::vector<std::string> m = {"citylangsplat"};
  m.insert(m.end(), config.baselines.begin(), config.baselines.end());
  return m;
}

fs::path RunContext::geometry() const { return config.rgb_model.empty() ? layout.rgb_ply() : fs::path(config.rgb_model); }

const std::string& RunContext::fingerprint(const std::string& of) const {
  const auto it = fingerprints.find(of);
  if (it == fingerprints.end()) throw std::logic_error("run: no fingerprint of " + of + " yet");
  return it->second;
}

namespace {

RunContext read_inputs(PipelineConfig c) {
  c.validate();
  if (c.out_dir.empty()) c.out_dir = RunLayout::of_scene(c.scene_dir).root();
  SceneOptions scene_options;
  scene_options.resolution_factor = c.resolution;
  scene_options.max_side = c.max_side;
  Scene scene = load_scene(c.scene_dir.string(), scene_options);
  if (scene.views.empty()) fail(c.scene_dir.string(), "the scene has no views");
  const SceneView& first = scene.views.front();
  if (c.resolution == 1 && std::max(first.source_camera.width, first.source_camera.height) > c.max_side && c.max_side > 0)
    log_info(cat("run: photos of ", first.source_camera.width, "x", first.source_camera.height, " are loaded at ",
                 first.camera.width, "x", first.camera.height, " (--max-side ", c.max_side,
                 ", as 3DGS does; --max-side 0 keeps them whole)"));
  // The language stages see the photos as LangSplat's preprocessing does (at most 1080 px tall): loaded
  // again at that size only where a photo is taller.
  Scene language_scene = scene;
  scene_options.max_height = c.feature_height;
  const bool taller = std::any_of(scene.views.begin(), scene.views.end(), [&](const SceneView& v) {
    return scale_to_resolution(v.camera, scene_options).height != v.camera.height;
  });
  if (c.resolution == 1 && taller) {
    language_scene = load_scene(c.scene_dir.string(), scene_options);
    const SceneView& l = language_scene.views.front();
    log_info(cat("run: the label maps, features and language fields use the photos at ", l.camera.width, "x",
                 l.camera.height, " (--feature-height ", c.feature_height, ", as LangSplat; 0: train-rgb's size)"));
  }
  SceneCityModel city = load_scene_city_model(c.city, c.city_transform, c.city_options, "run");
  const RunLayout layout(c.out_dir);
  label_map_dirs(scene, layout.labels());  // every view has a name its label maps can be written under
  FeatureSource source = resolve_feature_source(c, city.taxonomy);
  const std::string transform = c.city_transform;
  return RunContext{std::move(c), layout, std::move(scene), std::move(language_scene), std::move(city), std::move(source),
                    RunRecord(layout.run_json(), nlohmann::json::object()), transform, {},
                    PipelineOutcome::Finished, ""};
}

}  // namespace

RunContext open_run(const PipelineConfig& config) {
  RunContext run = read_inputs(config);
  const PipelineConfig& c = run.config;
  log_info(cat("run: ", run.scene.views.size(), " views (", run.scene.source, "), ", run.scene.points.size(),
               " sparse points; ", run.city.mesh.format, " ", run.city.mesh.version, " LoD", run.city.mesh.lod, ", ",
               run.city.mesh.num_triangles(), " triangles"));
  if (!run.source.note.empty()) log_warn("run: " + run.source.note);
  if (!run.source.warning.empty()) log_warn("run: " + run.source.warning);

  nlohmann::json header = {{"scene", fs::absolute(c.scene_dir).string()},
                           {"city_model", c.city},
                           {"models", run.source.models},
                           {"settings", pipeline_options().to_json(c)}};
  if (run.source.provider) header["provider"] = run.source.provider->spec();
  if (!run.source.warning.empty()) header["warning"] = run.source.warning;
  if (!run.source.note.empty()) header["note"] = run.source.note;
  // The settings as they ran: the schedule's counts, not the "0 = the provider's" of the options.
  header["settings"]["rgb_iterations"] = run.source.schedule.rgb_iterations;
  header["settings"]["language_iterations"] = run.source.schedule.language_iterations;
  header["settings"]["autoencoder_epochs"] = run.source.schedule.autoencoder_epochs;
  run.record = RunRecord(run.layout.run_json(), header);
  return run;
}

}  // namespace cls
