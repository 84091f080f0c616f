#pragma once
// Where the photos' GPS positions lie against the city model, in the model's CRS: the first check a
// user makes before georeferencing (are the photos and the model of the same place, and is the CRS
// right?), printed by `scene info --city`.
#include <array>
#include <vector>

#include "citymodel/semantic_mesh.h"
#include "georef/proj_crs.h"
#include "scene/exif_gps.h"

namespace cls {

struct GpsFootprint {
  size_t fixes = 0;
  // Horizontal distance of each fix from the model's bounding box (0 inside), in the CRS's units.
  double median_distance = 0, max_distance = 0;
  std::array<double, 4> box{};            // the model's x0, y0, x1, y1 in the CRS
  std::array<double, 2> model_heights{};  // the model's lowest and highest z
};

// cls::Error (from the projection) for a fix the CRS cannot represent. Without fixes, the model's box
// and heights only.
GpsFootprint gps_footprint(const std::vector<GpsFix>& fixes, const SemanticMesh& mesh, const GpsProjection& projection);

}  // namespace cls
