#pragma once
// The city-model options shared by `raycast`, `align` and `align-check`.
#include <string>

#include "citymodel/city_model.h"
#include "citymodel/scene_city_model.h"
#include "core/args.h"
#include "scene/scene.h"

namespace cls {

// The city model named on the command line: --city (required), --city-transform, --lod, --taxonomy.
// Args::parse rejects a missing --city or a bad --lod, so a command rejects its command line before it
// reads any file.
struct CityMeshOptions {
  std::string city, transform_path;  // transform_path "": the identity
  CityModelOptions model;

  // Declares the options into `args`, bound to these fields (their values are the defaults).
  Args& bind(Args& args) {
    return args.bind("city", city, "CityGML / CityJSON / CityJSONSeq city model")
        .required()
        .bind("city-transform", transform_path,
              "JSON similarity from the model's CRS into the scene frame (identity if not given)")
        .bind("lod", model.lod, "level of detail: 1, 2, 3 or highest", lod_codec())
        .bind("taxonomy", model.taxonomy_path, "taxonomy JSON (source types -> classes); the built-in one if not given");
  }
};

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

}  // namespace cls
