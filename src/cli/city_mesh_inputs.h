#pragma once
// The city-model options shared by `raycast`, `align-check`, `run` and `tile`.
#include <filesystem>
#include <string>

#include "citymodel/city_model.h"
#include "citymodel/scene_city_model.h"
#include "core/args.h"
#include "core/error.h"
#include "pipeline/pipeline_config.h"
#include "scene/scene.h"

namespace cls {

inline void add_city_mesh_options(Args& args) {
  args.option("city", "", "CityGML / CityJSON / CityJSONSeq city model (required)")
      .option("city-transform", "", "JSON similarity from the model's CRS into the scene frame (identity if not given)")
      .option("lod", "highest", "level of detail: 1, 2, 3 or highest")
      .option("taxonomy", "", "taxonomy JSON (source types -> classes); the built-in one if not given");
}

// The city-model options as given; cls::UsageError for a missing --city or a bad --lod, so a
// command can reject its command line before it reads any file.
struct CityMeshOptions {
  std::string city, transform_path;
  CityModelOptions model;
};

inline CityMeshOptions city_mesh_options(const Args& args, const std::string& command) {
  if (!args.has("city")) throw UsageError(command + ": --city is required (see --help)");
  CityMeshOptions o;
  o.city = args.get("city");
  o.transform_path = args.get("city-transform");
  o.model.lod = parse_lod_option(args.get("lod"));
  o.model.taxonomy_path = args.get("taxonomy");
  return o;
}

// The scene of `align` and `align-check`: poses and sparse points; the images are not read.
inline Scene load_scene_without_images(const std::string& dir) {
  SceneOptions options;
  options.check_images = false;
  return load_scene(dir, options);
}

// Reads and validates the city model named by the options (see scene_city_model.h).
inline SceneCityModel load_city_mesh_inputs(const CityMeshOptions& options, const std::string& command) {
  return load_scene_city_model(options.city, options.transform_path, options.model, command);
}

// `run` and `tile`: the city model of a scene's config file, each option overriding it.
inline void add_scene_city_options(Args& args) {
  args.option("config", "", "JSON config (default: SCENE_DIR/scene.json when it exists)")
      .option("city", "", "city model (overrides the config)")
      .option("city-transform", "", "city transform JSON (overrides the config)")
      .option("lod", "", "1, 2, 3 or highest (overrides the config; default highest)")
      .option("taxonomy", "", "taxonomy JSON (overrides the config; default built-in)");
}

// Fills the city-model fields of `c` from --config (or SCENE_DIR/scene.json) and the overriding options.
inline void read_scene_city_options(const Args& args, const std::filesystem::path& scene_dir, PipelineConfig& c) {
  const std::filesystem::path config =
      args.has("config") ? std::filesystem::path(args.get("config")) : scene_dir / "scene.json";
  if (args.has("config") && !std::filesystem::exists(config)) fail(config.string(), "config file not found");
  if (std::filesystem::exists(config)) read_scene_config(config, c);
  if (args.has("city")) c.city = args.get("city");
  if (args.has("city-transform")) c.city_transform = args.get("city-transform");
  if (args.has("taxonomy")) c.city_options.taxonomy_path = args.get("taxonomy");
  if (args.has("lod")) c.city_options.lod = parse_lod_option(args.get("lod"));
}

}  // namespace cls
