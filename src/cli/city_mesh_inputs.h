#pragma once
// The city-model options shared by `raycast`, `align-check` and `run`.
#include <string>

#include "citymodel/city_model.h"
#include "citymodel/scene_city_model.h"
#include "core/args.h"
#include "core/error.h"

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

// Reads and validates the city model named by the options (see scene_city_model.h).
inline SceneCityModel load_city_mesh_inputs(const CityMeshOptions& options, const std::string& command) {
  return load_scene_city_model(options.city, options.transform_path, options.model, command);
}

}  // namespace cls
