#include "scene/point_cloud.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "core/ply.h"
#include "core/strings.h"
#include "scene/las.h"

namespace cls {
namespace {

uint64_t stride_for(uint64_t count, uint64_t max_points) {
  return max_points == 0 || count <= max_points ? 1 : (count + max_points - 1) / max_points;
}

PointCloud read_ply_cloud(const std::string& path, uint64_t max_points) {
  const PlyVertices v = read_ply_vertices(path);
  const PlyProperty &x = v.require("x"), &y = v.require("y"), &z = v.require("z");
  // Colour under either of the names writers use; 16-bit channels scaled to 8 bit.
  std::array<const PlyProperty*, 3> colour{};
  for (const char* prefix : {"", "diffuse_"})
    if (!colour[0]) colour = {v.find(std::string(prefix) + "red"), v.find(std::string(prefix) + "green"),
                              v.find(std::string(prefix) + "blue")};
  const bool has_colour = colour[0] && colour[1] && colour[2];
  const double colour_scale = has_colour && colour[0]->size == 2 ? 255.0 / 65535.0 : 1.0;
  PointCloud out;
  out.total = v.count;
  const uint64_t stride = stride_for(v.count, max_points);
  for (uint64_t i = 0; i < v.count; i += stride) {
    out.xyz.push_back({v.finite_value(i, x), v.finite_value(i, y), v.finite_value(i, z)});
    std::array<uint8_t, 3> c{128, 128, 128};
    if (has_colour)
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<uint8_t>(std::clamp(v.finite_value(i, *colour[k]) * colour_scale + 0.5, 0.0, 255.0));
    out.rgb.push_back(c);
  }
  return out;
}

PointCloud read_las_cloud(const std::string& path, uint64_t max_points) {
  const LasHeader h = read_las_header(path);
  LasPoints las = read_las(path, stride_for(h.point_count, max_points));
  PointCloud out;
  out.total = h.point_count;
  out.xyz = std::move(las.xyz);
  out.rgb = las.rgb.empty() ? std::vector<std::array<uint8_t, 3>>(out.xyz.size(), {128, 128, 128}) : std::move(las.rgb);
  return out;
}

}  // namespace

PointCloud read_point_cloud(const std::string& path, uint64_t max_points) {
  const std::string ext = ascii_lower(std::filesystem::path(path).extension().string());
  if (ext == ".ply") return read_ply_cloud(path, max_points);
  if (is_las_path(path)) return read_las_cloud(path, max_points);
  fail(path, "point cloud format '" + ext + "' is not read (LAS or PLY)");
}

}  // namespace cls
