#include "tiles/tile_plan.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"

namespace cls {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// The set covers at least min_share of the view's building pixels (and at least one).
bool sees_buildings(const std::vector<char>& in_set, const ViewBuildings& view, double min_share) {
  int64_t own = 0;
  for (const auto& [b, p] : view.pixels)
    if (in_set[b]) own += p;
  return own > 0 && static_cast<double>(own) >= min_share * static_cast<double>(view.total);
}

}  // namespace

std::vector<int> views_of_buildings(const std::vector<char>& in_set, const BuildingPixels& pixels, double min_share) {
  std::vector<int> views;
  for (size_t v = 0; v < pixels.size(); ++v)
    if (sees_buildings(in_set, pixels[v], min_share)) views.push_back(static_cast<int>(v));
  return views;
}

std::vector<int> views_of_tile(const std::vector<char>& in_set, const TileCell& cell, const BuildingPixels& pixels,
                               double min_share) {
  std::vector<int> views;
  for (size_t v = 0; v < pixels.size(); ++v)
    if (sees_buildings(in_set, pixels[v], min_share) || cell.contains(pixels[v].camera_x, pixels[v].camera_y))
      views.push_back(static_cast<int>(v));
  return views;
}

Partition partition_buildings(const std::vector<BuildingFootprint>& footprints, const BuildingPixels& pixels,
                              int max_images, double min_share) {
  Partition result;
  std::vector<char> in_set(footprints.size(), 0);
  std::function<void(std::vector<int>, TileCell)> split = [&](std::vector<int> set, TileCell cell) {
    for (int b : set) in_set[b] = 1;
    std::vector<int> views = views_of_tile(in_set, cell, pixels, min_share);
    for (int b : set) in_set[b] = 0;
    if (static_cast<int>(views.size()) > max_images && set.size() > 1) {
      double lo[2] = {TileCell::kInf, TileCell::kInf}, hi[2] = {-TileCell::kInf, -TileCell::kInf};
      for (int b : set) {
        const double c[2] = {footprints[b].cx(), footprints[b].cy()};
        for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], c[a]), hi[a] = std::max(hi[a], c[a]);
      }
      const int a = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
      if (hi[a] > lo[a]) {  // else every centre coincides: nothing to cut
        auto centre = [&](int b) { return a == 0 ? footprints[b].cx() : footprints[b].cy(); };
        std::sort(set.begin(), set.end(), [&](int p, int q) { return centre(p) < centre(q) || (centre(p) == centre(q) && p < q); });
        // The median cut, moved to the nearest gap between distinct centres (one exists: hi > lo).
        const size_t n = set.size(), k = n / 2;
        size_t cut_at = 0;
        for (size_t d = 0; cut_at == 0; ++d)
          for (size_t cand : {k + d, k - d})
            if (cand > 0 && cand < n && centre(set[cand - 1]) < centre(set[cand])) {
              cut_at = cand;
              break;
            }
        const double cut = 0.5 * (centre(set[cut_at - 1]) + centre(set[cut_at]));
        TileCell left = cell, right = cell;
        (a == 0 ? left.x1 : left.y1) = cut;
        (a == 0 ? right.x0 : right.y0) = cut;
        split(std::vector<int>(set.begin(), set.begin() + static_cast<long>(cut_at)), left);
        split(std::vector<int>(set.begin() + static_cast<long>(cut_at), set.end()), right);
        return;
      }
    }
    std::sort(set.begin(), set.end());
    result.tiles.push_back({std::move(set), cell, std::move(views)});
  };
  std::vector<int> seen;
  for (size_t b = 0; b < footprints.size(); ++b) {
    in_set[b] = 1;
    (views_of_buildings(in_set, pixels, min_share).empty() ? result.unseen : seen).push_back(static_cast<int>(b));
    in_set[b] = 0;
  }
  if (!seen.empty()) split(seen, TileCell{});
  return result;
}

namespace {

// Infinite sides are written as null (JSON has no infinity).
json side(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
double side_of(const json& v, double infinite) { return v.is_null() ? infinite : v.get<double>(); }

}  // namespace

void write_tile_plan(const fs::path& file, const TilePlan& plan) {
  json tiles = json::array();
  for (const Tile& t : plan.tiles)
    tiles.push_back({{"name", t.name},
                     {"buildings", t.buildings},
                     {"cell", {side(t.cell.x0), side(t.cell.y0), side(t.cell.x1), side(t.cell.y1)}},
                     {"images", t.images}});
  const json j = {{"scene", plan.scene.string()},     {"city_model", plan.city_model},
                  {"city_transform", plan.city_transform}, {"taxonomy", plan.taxonomy},
                  {"lod", plan.lod},                   {"max_images", plan.max_images},
                  {"min_share", plan.min_share},
                  {"unseen", plan.unseen},             {"tiles", tiles}};
  write_text_atomic(file, j.dump(2) + "\n");
}

TilePlan read_tile_plan(const fs::path& file) {
  TilePlan plan;
  try {
    const json j = json::parse(read_text_file(file));
    plan.scene = j.at("scene").get<std::string>();
    plan.city_model = j.at("city_model").get<std::string>();
    plan.city_transform = j.at("city_transform").get<std::string>();
    plan.taxonomy = j.at("taxonomy").get<std::string>();
    plan.lod = j.at("lod").get<int>();
    plan.max_images = j.at("max_images").get<int>();
    plan.min_share = j.at("min_share").get<double>();
    plan.unseen = j.value("unseen", std::vector<std::string>{});
    for (const json& t : j.at("tiles")) {
      Tile tile;
      tile.name = t.at("name").get<std::string>();
      tile.buildings = t.at("buildings").get<std::vector<std::string>>();
      const json& c = t.at("cell");
      if (!c.is_array() || c.size() != 4) fail(file.string(), "tile " + tile.name + ": \"cell\" must be [x0, y0, x1, y1]");
      tile.cell = {side_of(c[0], -TileCell::kInf), side_of(c[1], -TileCell::kInf), side_of(c[2], TileCell::kInf),
                   side_of(c[3], TileCell::kInf)};
      tile.images = t.at("images").get<std::vector<std::string>>();
      if (tile.name.empty() || tile.name.find('/') != std::string::npos || tile.name[0] == '.')
        fail(file.string(), "tile name '" + tile.name + "' is not a plain directory name");
      plan.tiles.push_back(std::move(tile));
    }
  } catch (const json::exception& e) {
    fail(file.string(), std::string("not a valid tiles.json: ") + e.what());
  }
  if (plan.tiles.empty()) fail(file.string(), "no tiles");
  return plan;
}

TilePlan read_tiles_dir(const fs::path& tiles_dir) {
  const fs::path file = tiles_dir / "tiles.json";
  if (!fs::exists(file)) fail(file.string(), "missing: make the tiles with `citylangsplat tile` first");
  return read_tile_plan(file);
}

}  // namespace cls
