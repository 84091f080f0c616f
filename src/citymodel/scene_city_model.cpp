#include "citymodel/scene_city_model.h"

#include <cmath>

#include "core/error.h"
#include "core/log.h"

namespace cls {

SceneCityModel load_scene_city_model(const std::string& city_path, const std::string& transform_path,
                                     const CityModelOptions& options, const std::string& context) {
  SceneCityModel in;
  in.taxonomy = load_taxonomy(options);
  if (!transform_path.empty()) in.transform = read_city_transform(transform_path);
  in.mesh = load_city_model(city_path, in.taxonomy, options.lod);
  if (in.mesh.num_triangles() == 0) fail(city_path, "the city model has no triangles at the requested LoD");
  in.vertices = scene_vertices(in.mesh, in.transform);
  float extent = 0;
  for (const auto& v : in.vertices)
    extent = std::fmax(extent, std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))));
  if (extent > 1e5f && transform_path.empty())
    log_info(cat(context, ": no city transform given: the city mesh lies where its CRS puts it, up to ", extent,
                 " units from the scene origin, until georef (run --georef) finds the transform from a Pix4D/OPF "
                 "project's frame or the photos' EXIF GPS, or --city-transform gives it"));
  else if (extent > 1e5f)
    log_warn(cat(context, ": the city mesh reaches ", extent, " units from the scene origin; float precision there is ",
                 "coarse (give --city-transform into the scene's local frame)"));
  return in;
}

}  // namespace cls
