#pragma once
// The city-model options shared by `raycast` and `align-check`, and loading the model into the
// scene frame. Header-only because the CLI's sources are listed one by one in CMakeLists.txt.
#include <cmath>
#include <string>
#include <vector>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "cli/args.h"
#include "core/error.h"
#include "core/log.h"

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

struct CityMeshInputs {
  Taxonomy taxonomy;
  CityTransform transform;
  SemanticMesh mesh;
  std::vector<Vec3f> vertices;  // mesh vertices in the scene frame
};

// Reads and validates everything; cls::Error naming the file on any problem, so a command can
// load all its inputs before it writes anything.
inline CityMeshInputs load_city_mesh_inputs(const CityMeshOptions& options, const std::string& command) {
  CityMeshInputs in;
  in.taxonomy = load_taxonomy(options.model);
  if (!options.transform_path.empty()) in.transform = read_city_transform(options.transform_path);
  in.mesh = load_city_model(options.city, in.taxonomy, options.model.lod);
  if (in.mesh.num_triangles() == 0) fail(options.city, "the city model has no triangles at the requested LoD");
  in.vertices = scene_vertices(in.mesh, in.transform);
  float extent = 0;
  for (const auto& v : in.vertices) extent = std::fmax(extent, std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))));
  if (extent > 1e5f)
    log_warn(cat(command, ": the city mesh reaches ", extent, " units from the scene origin; float precision there is ",
                 "coarse (give --city-transform into the scene's local frame)"));
  return in;
}

}  // namespace cls
