#pragma once
// The city model as the scene sees it: taxonomy, transform, semantic mesh and its vertices in the
// scene frame. Loaded (and validated) in one call, so commands read every input before writing.
#include <string>
#include <vector>

#include "citymodel/city_model.h"
#include "citymodel/city_transform.h"
#include "citymodel/semantic_mesh.h"
#include "citymodel/taxonomy.h"
#include "core/math.h"

namespace cls {

struct SceneCityModel {
  Taxonomy taxonomy;
  CityTransform transform;
  SemanticMesh mesh;
  std::vector<Vec3f> vertices;  // mesh vertices in the scene frame
};

// `transform_path` "" = identity. cls::Error naming the file on any problem; an empty mesh is an
// error. Warns (prefixed with `context`) when the mesh lies far from the scene origin.
SceneCityModel load_scene_city_model(const std::string& city_path, const std::string& transform_path,
                                     const CityModelOptions& options, const std::string& context);

}  // namespace cls
