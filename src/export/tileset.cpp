#include "export/tileset.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.h"
#include "core/log.h"

namespace cls {

std::array<double, 16> ecef_tile_transform(const CrsToGeocentric& to_ecef, const Vec3d& origin) {
  auto ecef = [&](const Vec3d& p) {
    const auto xyz = to_ecef(p.x, p.y, p.z);
    if (!xyz) throw Error(cat("export: PROJ cannot place (", p.x, ", ", p.y, ", ", p.z, ") of the city model's CRS on the globe"));
    return Vec3d{(*xyz)[0], (*xyz)[1], (*xyz)[2]};
  };
  constexpr double h = 10;
  std::array<double, 16> m{};
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d step{0, 0, 0};
    step[axis] = h;
    const Vec3d column = (1 / (2 * h)) * (ecef(origin + step) - ecef(origin - step));
    for (int r = 0; r < 3; ++r) m[4 * axis + r] = column[r];
  }
  const Vec3d centre = ecef(origin);
  for (int r = 0; r < 3; ++r) m[12 + r] = centre[r];
  m[15] = 1;
  return m;
}

std::string splat_tile_uri(const SplatTile& tile) { return "tiles/" + tile.name + ".glb"; }

nlohmann::json tileset_json(const std::array<double, 16>& transform, const SplatTileTree& tree,
                            const nlohmann::json& extras) {
  std::function<nlohmann::json(int)> tile_json = [&](int t) {
    const SplatTile& tile = tree.tiles[t];
    nlohmann::json j{{"boundingVolume", {{"box", tile.box}}},
                     {"geometricError", tile.geometric_error},
                     {"refine", "ADD"},
                     {"content", {{"uri", splat_tile_uri(tile)}}}};
    for (const int c : tile.children) j["children"].push_back(tile_json(c));
    return j;
  };
  nlohmann::json root = tile_json(0);
  root["transform"] = transform;
  const std::array<double, 12>& box = tree.tiles[0].box;
  const double diagonal = 2 * std::sqrt(box[3] * box[3] + box[7] * box[7] + box[11] * box[11]);
  nlohmann::json tileset{{"asset", {{"version", "1.1"}, {"generator", "citylangsplat " CLS_VERSION}}},
                         {"geometricError", std::max(diagonal, tree.tiles[0].geometric_error)},
                         {"root", root}};
  if (!extras.empty()) tileset["asset"]["extras"] = extras;
  return tileset;
}

void declare_gltf_extensions(nlohmann::json& tileset, const nlohmann::json& gltf) {
  const auto add = [](nlohmann::json& list, const std::string& name) {
    if (!list.is_array()) list = nlohmann::json::array();
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  add(tileset["extensionsUsed"], "3DTILES_content_gltf");
  nlohmann::json& content = tileset["extensions"]["3DTILES_content_gltf"];
  for (const char* key : {"extensionsUsed", "extensionsRequired"})
    for (const auto& name : gltf.value(key, nlohmann::json::array())) add(content[key], name.get<std::string>());
}

}  // namespace cls
