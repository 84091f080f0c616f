#pragma once
// A photogrammetric point cloud a user brings to start the Gaussians from (PIX4Dmapper's densified
// cloud, any LAS or PLY of the scene): positions and colours, thinned to a point budget.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace cls {

struct PointCloud {
  std::vector<Vec3d> xyz;
  std::vector<std::array<uint8_t, 3>> rgb;  // grey (128) for a cloud without colours
  uint64_t total = 0;                       // points in the file(s) before thinning
};

// Reads LAS (scene/las.h) or PLY (core/ply.h: x, y, z, and red/green/blue or diffuse_red/...
// when present, 8 or 16 bit) by the file's extension, keeping every k-th point so that at most
// `max_points` remain (0: all). cls::Error naming the file otherwise (LAZ, another extension, a
// coordinate that is not finite, ...).
PointCloud read_point_cloud(const std::string& path, uint64_t max_points);

}  // namespace cls
