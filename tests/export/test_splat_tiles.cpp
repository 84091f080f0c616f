// The quadtree of splat tiles (export/splat_tiles.h) and its tileset.json (export/tileset.h), against
// brute-force walks of the tree and hand cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <random>
#include <set>

#include "export/splat_tiles.h"
#include "export/tileset.h"

namespace cls {
namespace {
using nlohmann::json;

struct Cloud {
  std::vector<Vec3d> centres;
  std::vector<double> radii, importance;
};

Cloud random_cloud(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-50, 50), y(-30, 30), z(0, 20), r(0.01, 0.5), w(0, 1);
  Cloud c;
  for (int i = 0; i < n; ++i) {
    c.centres.push_back({x(rng), y(rng), z(rng)});
    c.radii.push_back(r(rng));
    c.importance.push_back(w(rng));
  }
  return c;
}

// The Gaussians of tile t and all below it.
std::vector<int64_t> subtree(const SplatTileTree& tree, int t) {
  std::vector<int64_t> all = tree.tiles[t].splats;
  for (const int c : tree.tiles[t].children) {
    const std::vector<int64_t> below = subtree(tree, c);
    all.insert(all.end(), below.begin(), below.end());
  }
  return all;
}

TEST(SplatTiles, EveryGaussianLiesInExactlyOneTileAndNoTileHoldsMoreThanTheLimit) {
  const Cloud c = random_cloud(1000, 1);
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 64);
  ASSERT_GT(tree.tiles.size(), 1u);
  std::vector<int> seen(c.centres.size(), 0);
  for (const SplatTile& t : tree.tiles) {
    EXPECT_LE(t.splats.size(), 64u) << t.name;
    EXPECT_FALSE(t.splats.empty()) << t.name;
    EXPECT_TRUE(std::is_sorted(t.splats.begin(), t.splats.end())) << t.name;
    for (const int64_t i : t.splats) ++seen[i];
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(c.centres.size()));
}

TEST(SplatTiles, EachBoxHoldsItsSubtreeAndItsChildrensBoxes) {
  const Cloud c = random_cloud(800, 2);
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 50);
  for (size_t t = 0; t < tree.tiles.size(); ++t) {
    const std::array<double, 12>& b = tree.tiles[t].box;
    for (const int64_t i : subtree(tree, static_cast<int>(t)))
      for (int a = 0; a < 3; ++a) {
        EXPECT_LE(std::abs(c.centres[i][a] - b[a]) + c.radii[i], b[3 + 4 * a] + 1e-9) << tree.tiles[t].name;
      }
    for (const int ch : tree.tiles[t].children)
      for (int a = 0; a < 3; ++a) {
        const std::array<double, 12>& cb = tree.tiles[ch].box;
        EXPECT_LE(std::abs(cb[a] - b[a]) + cb[3 + 4 * a], b[3 + 4 * a] + 1e-9);
      }
  }
}

TEST(SplatTiles, ACoarseTileKeepsTheMostImportantGaussiansOfItsArea) {
  const Cloud c = random_cloud(1000, 3);
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 40);
  int inner = 0;
  for (size_t t = 0; t < tree.tiles.size(); ++t) {
    if (tree.tiles[t].children.empty()) continue;
    ++inner;
    double least_kept = INFINITY, most_below = -INFINITY;
    for (const int64_t i : tree.tiles[t].splats) least_kept = std::min(least_kept, c.importance[i]);
    for (const int ch : tree.tiles[t].children)
      for (const int64_t i : subtree(tree, ch)) most_below = std::max(most_below, c.importance[i]);
    EXPECT_GE(least_kept, most_below) << tree.tiles[t].name;
  }
  EXPECT_GT(inner, 1);
}

TEST(SplatTiles, ErrorsShrinkDownTheTreeAndLeavesHaveNone) {
  const Cloud c = random_cloud(1000, 4);
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 30);
  for (const SplatTile& t : tree.tiles) {
    if (t.children.empty()) EXPECT_EQ(t.geometric_error, 0) << t.name;
    else EXPECT_GT(t.geometric_error, 0) << t.name;
    for (const int ch : t.children) {
      EXPECT_LE(tree.tiles[ch].geometric_error, t.geometric_error);
      EXPECT_EQ(tree.tiles[ch].name.substr(0, t.name.size()), t.name);  // "r03" under "r0"
      EXPECT_EQ(tree.tiles[ch].name.size(), t.name.size() + 1);
    }
  }
  // Hand case: five Gaussians on a 2 m x 2 m square, one per tile. The root keeps the most important
  // (the centre), its error the spacing of one Gaussian over 4 m2: 2 m; each corner is a quadrant's leaf.
  const std::vector<Vec3d> square{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}, {1, 1, 0}};
  const SplatTileTree hand = build_splat_tiles(square, {0, 0, 0, 0, 0}, {1, 1, 1, 1, 5}, 1);
  ASSERT_EQ(hand.tiles.size(), 5u);
  EXPECT_EQ(hand.tiles[0].splats, std::vector<int64_t>{4});
  EXPECT_DOUBLE_EQ(hand.tiles[0].geometric_error, 2);
  const std::vector<std::string> names{"r0", "r1", "r2", "r3"};
  for (int k = 0; k < 4; ++k) {
    EXPECT_EQ(hand.tiles[hand.tiles[0].children[k]].name, names[k]);
    EXPECT_EQ(hand.tiles[hand.tiles[0].children[k]].splats, std::vector<int64_t>{k});  // (x >= 1) + 2 (y >= 1)
  }
}

TEST(SplatTiles, AModelWithinTheLimitIsOneTileAndCoincidentGaussiansEndInAChain) {
  const Cloud c = random_cloud(100, 5);
  const SplatTileTree one = build_splat_tiles(c.centres, c.radii, c.importance, 100);
  ASSERT_EQ(one.tiles.size(), 1u);
  EXPECT_EQ(one.tiles[0].name, "r");
  EXPECT_EQ(one.tiles[0].splats.size(), 100u);
  EXPECT_EQ(one.tiles[0].geometric_error, 0);
  // 5000 Gaussians at one point, one per tile: a chain 5000 deep, built without recursion.
  const SplatTileTree chain = build_splat_tiles(std::vector<Vec3d>(5000, {1, 2, 3}), std::vector<double>(5000, 0.1),
                                                std::vector<double>(5000, 1), 1);
  EXPECT_EQ(chain.tiles.size(), 5000u);
  EXPECT_THROW(build_splat_tiles({}, {}, {}, 1), std::invalid_argument);
  EXPECT_THROW(build_splat_tiles(c.centres, c.radii, c.importance, 0), std::invalid_argument);
}

TEST(SplatTiles, FarFloatersJoinTheBorderCellsInsteadOfWideningThem) {
  // 1000 Gaussians on a 100 m x 60 m district and 5 floaters 20 km away: the root's error (the spacing
  // of its Gaussians over its cell) is that of the district's cell, and the floaters still lie in a tile
  // whose box holds them.
  Cloud c = random_cloud(1000, 7);
  for (int k = 0; k < 5; ++k) {
    c.centres.push_back({20000.0 + k, -20000.0, 100});
    c.radii.push_back(50);
    c.importance.push_back(0.5);
  }
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 100);
  EXPECT_LE(tree.tiles[0].geometric_error, std::sqrt(100.0 * 60.0 / 100) * 1.01);
  EXPECT_GT(tree.tiles[0].box[3], 10000);  // the root's box holds the floaters
}

TEST(Tileset, TheTreeNestsWithItsBoxesErrorsAndContentsAndTheTransformOnTheRoot) {
  const Cloud c = random_cloud(300, 6);
  const SplatTileTree tree = build_splat_tiles(c.centres, c.radii, c.importance, 40);
  const std::array<double, 16> m{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 10, 20, 30, 1};
  const json t = tileset_json(m, tree, json::object());
  EXPECT_EQ(t["asset"]["version"], "1.1");
  EXPECT_EQ(t["root"]["transform"].get<std::vector<double>>(), std::vector<double>(m.begin(), m.end()));
  const std::array<double, 12>& box = tree.tiles[0].box;
  EXPECT_DOUBLE_EQ(t["geometricError"].get<double>(),
                   std::max(2 * std::sqrt(box[3] * box[3] + box[7] * box[7] + box[11] * box[11]), tree.tiles[0].geometric_error));
  // Walk the JSON and the tree together: every tile once, in the same shape.
  std::set<std::string> uris;
  std::function<void(const json&, int)> walk = [&](const json& j, int k) {
    const SplatTile& tile = tree.tiles[k];
    EXPECT_EQ(j["content"]["uri"], "tiles/" + tile.name + ".glb");
    EXPECT_EQ(j["refine"], "ADD");
    EXPECT_EQ(j["geometricError"].get<double>(), tile.geometric_error);
    EXPECT_EQ(j["boundingVolume"]["box"].get<std::vector<double>>(), std::vector<double>(tile.box.begin(), tile.box.end()));
    EXPECT_EQ(k == 0, j.contains("transform"));
    uris.insert(j["content"]["uri"].get<std::string>());
    const json children = j.value("children", json::array());
    ASSERT_EQ(children.size(), tile.children.size());
    for (size_t i = 0; i < children.size(); ++i) walk(children[i], tile.children[i]);
  };
  walk(t["root"], 0);
  EXPECT_EQ(uris.size(), tree.tiles.size());
}

TEST(Tileset, TheContentsGltfExtensionsAreDeclaredOnceEach) {
  json t = {{"asset", {{"version", "1.1"}}}};
  declare_gltf_extensions(t, {{"extensionsUsed", {"KHR_gaussian_splatting", "EXT_mesh_features"}},
                              {"extensionsRequired", {"KHR_gaussian_splatting"}}});
  declare_gltf_extensions(t, {{"extensionsUsed", {"KHR_gaussian_splatting", "EXT_structural_metadata"}}});
  declare_gltf_extensions(t, json::object());
  EXPECT_EQ(t["extensionsUsed"], json::array({"3DTILES_content_gltf"}));
  const json& c = t["extensions"]["3DTILES_content_gltf"];
  EXPECT_EQ(c["extensionsUsed"], json::array({"KHR_gaussian_splatting", "EXT_mesh_features", "EXT_structural_metadata"}));
  EXPECT_EQ(c["extensionsRequired"], json::array({"KHR_gaussian_splatting"}));
}

}  // namespace
}  // namespace cls
