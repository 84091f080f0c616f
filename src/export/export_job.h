#pragma once
// `citylangsplat export`: a trained model as glTF or a 3D Tiles tileset (issue 35, docs/export.md). The input is a `run`
// output, a language model directory or a 3DGS PLY; the splats go out as splat_gltf.h writes them,
// with their city objects and text query scores when the model has them, placed in the city model's
// CRS when the label maps recorded the transform (labels/city_transform.json):
//   glTF (x, y, z) = (E, U, -N) of  CRS - origin,  the node's matrix = Y_up * T(-origin) * inverse(city transform)
// so glTF's y is up and its coordinates stay small (origin: the splats' mean in the CRS, in whole
// metres, kept in the asset's extras with the CRS). Without that record the splats stay in the frame
// they were trained in, and the extras say so.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "citymodel/city_transform.h"

namespace cls {

struct ExportOptions {
  std::string input;                   // a run output, a language model directory or a .ply
  std::string format = "glb";          // glb, gltf, or 3dtiles (a directory: tileset.json + tiles/*.glb)
  int64_t tile_splats = 100000;        // 3dtiles: the most Gaussians in one tile (splat_tiles.h)
  std::string compress;                // none or spz (KHR_gaussian_splatting_compression_spz_2); "": spz for 3dtiles
  std::string spz_axes;                // luf or cesium (spz.h's SpzAxes); "": cesium for 3dtiles, else luf
  std::string out;                     // "" = beside the model: gaussians.<format>, gaussians_3dtiles/
  std::string method = "citylangsplat";  // the language model of a run output
  std::vector<std::string> queries;    // texts whose per-splat scores go out as property attributes
  std::string level = "best";          // the queries' level: 1, 2, 3 or best (LangSplat's choice per text)
  bool georeference = true;            // place the splats in the city model's CRS when the transform is known
};

// The glTF node matrix (column-major) that takes scene coordinates to y-up coordinates of the city
// model's CRS minus `origin`: the inverse of `scene_from_crs`, the shift, then (E, N, U) -> (E, U, -N).
std::array<double, 16> gltf_city_matrix(const CityTransform& scene_from_crs, const Vec3d& origin);

// Writes the asset and returns what it wrote ({"file", "gaussians", "tiles", "semantics", "queries", "frame"}).
// cls::UsageError for bad options, cls::Error naming the file for unreadable inputs.
nlohmann::json run_export(const ExportOptions& options);

}  // namespace cls
