// The enriched city model's parts on hand-made cases: rings back from the mesh builder's triangles,
// the CityJSON structure of a wall with a window, and the covered fraction of a wall half in view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "citymodel/city_objects.h"
#include "citymodel/city_transform.h"
#include "citymodel/cityjson_reader.h"
#include "citymodel/mesh_builder.h"
#include "core/npy.h"
#include "export/city_observations.h"
#include "export/cityjson_writer.h"
#include "export/opening_proposals.h"
#include "raycast/label_map_io.h"
#include "scene/scene_test_util.h"

namespace cls {
namespace {

using nlohmann::json;

// A rotation of `ring` that starts at its smallest vertex, so that two rings compare as cycles.
std::vector<uint32_t> canonical(std::vector<uint32_t> ring) {
  std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end()), ring.end());
  return ring;
}

// The positions of a ring's vertices in the mesh, rotated to start at the smallest (x, y, z).
std::vector<std::array<double, 3>> positions(const std::vector<uint32_t>& ring, const SemanticMesh& mesh) {
  std::vector<std::array<double, 3>> p;
  for (const uint32_t v : ring)
    p.push_back({mesh.vertices[v][0] + mesh.origin[0], mesh.vertices[v][1] + mesh.origin[1], mesh.vertices[v][2] + mesh.origin[2]});
  std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  return p;
}

// A wall of 4 x 3 m in the plane y = 0 (normal -y: counter-clockwise seen from y < 0), with a window of
// 1 x 1 m cut out of it and added as its own polygon.
struct WallWithWindow {
  Taxonomy taxonomy = Taxonomy::builtin();
  SemanticMesh mesh;
  Ring outer = {{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}};
  Ring hole = {{1, 0, 1}, {1, 0, 2}, {2, 0, 2}, {2, 0, 1}};  // clockwise seen from y < 0
  WallWithWindow() {
    MeshBuilder b(taxonomy);
    const int building = b.add_entity(3, taxonomy.find("building"), -1, "house");
    const int wall = b.add_entity(2, taxonomy.find("wall"), building, "wall-1");
    const int window = b.add_entity(1, taxonomy.find("window"), wall, "window-1");
    b.add_polygon({outer, hole}, taxonomy.find("wall"), wall, "p-wall");
    b.add_polygon({{hole.rbegin(), hole.rend()}}, taxonomy.find("window"), window, "p-window");
    mesh = b.finish();
  }
};

TEST(CityJsonWriter, PolygonRingsAreTheBuildersRingsWithTheExteriorFirst) {
  const WallWithWindow w;
  std::vector<std::array<uint32_t, 3>> wall_triangles;
  for (size_t t = 0; t < w.mesh.triangles.size(); ++t)
    if (w.mesh.tri_polygon[t] == 0) wall_triangles.push_back(w.mesh.triangles[t]);
  ASSERT_GE(wall_triangles.size(), 8u);  // a quad with a quad hole: at least 8 triangles
  const auto rings = polygon_rings(wall_triangles, w.mesh.vertices);
  ASSERT_EQ(rings.size(), 2u);
  // The exterior in the input's order (counter-clockwise about the wall's normal), then the hole reversed.
  const std::vector<std::array<double, 3>> outer(w.outer.begin(), w.outer.end());
  EXPECT_EQ(positions(rings[0], w.mesh), outer);
  std::vector<std::array<double, 3>> hole(w.hole.begin(), w.hole.end());
  std::rotate(hole.begin(), std::min_element(hole.begin(), hole.end()), hole.end());
  EXPECT_EQ(positions(rings[1], w.mesh), hole);
  // One triangle: itself; two triangles sharing an edge: the quad; two apart: two rings; an open fan: none.
  EXPECT_EQ(canonical(polygon_rings({{0, 1, 2}}, w.mesh.vertices).at(0)), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(canonical(polygon_rings({{0, 1, 2}, {0, 2, 3}}, w.mesh.vertices).at(0)), (std::vector<uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(polygon_rings({{0, 1, 2}, {3, 4, 5}}, w.mesh.vertices).size(), 2u);
  EXPECT_TRUE(polygon_rings({}, w.mesh.vertices).empty());
}

TEST(CityJsonWriter, AWallWithAWindowIsABuildingWithTwoSemanticSurfaces) {
  const WallWithWindow w;
  const CityJsonDocument doc = semantic_mesh_cityjson(w.mesh, w.taxonomy, "https://www.opengis.net/def/crs/EPSG/0/25832");
  const json& d = doc.document;
  EXPECT_EQ(d["type"], "CityJSON");
  EXPECT_EQ(d["version"], "2.0");
  EXPECT_EQ(d["metadata"]["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/25832");
  ASSERT_EQ(d["CityObjects"].size(), 1u);
  const json& house = d["CityObjects"]["house"];
  EXPECT_EQ(house["type"], "Building");
  const json& g = house["geometry"][0];
  EXPECT_EQ(g["type"], "MultiSurface");
  ASSERT_EQ(g["boundaries"].size(), 2u);
  EXPECT_EQ(g["boundaries"][0].size(), 2u);  // the wall: exterior and hole
  EXPECT_EQ(g["boundaries"][1].size(), 1u);  // the window
  const json& s = g["semantics"];
  EXPECT_EQ(s["surfaces"][0]["type"], "WallSurface");
  EXPECT_EQ(s["surfaces"][1]["type"], "Window");
  EXPECT_EQ(s["surfaces"][1]["parent"], 0);
  EXPECT_EQ(s["surfaces"][0]["children"], json::array({1}));
  EXPECT_EQ(s["values"], json::array({0, 1}));
  // 8 distinct corners, shared between the wall's hole and the window; coordinates back in the CRS.
  ASSERT_EQ(d["vertices"].size(), 8u);
  const json& t = d["transform"];
  for (const json& v : d["vertices"])
    for (int a = 0; a < 3; ++a) {
      const double x = v[a].get<double>() * t["scale"][a].get<double>() + t["translate"][a].get<double>();
      EXPECT_NEAR(x, std::round(x), 1e-9);  // the hand case's corners are whole metres
    }
  // Where each entity's attributes go.
  ASSERT_EQ(doc.places.size(), 3u);
  EXPECT_TRUE(doc.places[0].is_object);
  EXPECT_EQ(doc.places[1].object, "house");
  EXPECT_EQ(doc.places[1].surface, 0);
  EXPECT_EQ(doc.places[2].surface, 1);
  EXPECT_EQ(cityjson_reference_system("urn:adv:crs:ETRS89_UTM32*DE_DHHN92_NH"), "https://www.opengis.net/def/crs/EPSG/0/25832");
  EXPECT_EQ(cityjson_reference_system("no such CRS"), "");
}

TEST(CityJsonWriter, ASequenceReadsBackAsTheDocumentItCameFrom) {
  // Two buildings, the first with a BuildingPart that has its own wall: two features, the part in the
  // first with its parent; each feature with only its own vertices.
  const Taxonomy taxonomy = Taxonomy::builtin();
  MeshBuilder b(taxonomy);
  const int house = b.add_entity(3, taxonomy.find("building"), -1, "house");
  const int wall = b.add_entity(2, taxonomy.find("wall"), house, "wall-1");
  const int part = b.add_entity(3, taxonomy.find("building"), house, "house-part");
  const int part_wall = b.add_entity(2, taxonomy.find("wall"), part, "wall-2");
  const int shed = b.add_entity(3, taxonomy.find("building"), -1, "shed");
  const int roof = b.add_entity(2, taxonomy.find("roof"), shed, "roof-1");
  b.add_polygon({{{0, 0, 0}, {4, 0, 0}, {4, 0, 3}, {0, 0, 3}}}, taxonomy.find("wall"), wall, "p1");
  b.add_polygon({{{4, 0, 0}, {4, 5, 0}, {4, 5, 3}, {4, 0, 3}}}, taxonomy.find("wall"), part_wall, "p2");
  b.add_polygon({{{10, 0, 2}, {12, 0, 2}, {12, 2, 2}, {10, 2, 2}}}, taxonomy.find("roof"), roof, "p3");
  const SemanticMesh mesh = b.finish();
  const json doc = semantic_mesh_cityjson(mesh, taxonomy, "https://www.opengis.net/def/crs/EPSG/0/25832").document;
  const std::vector<json> lines = cityjson_sequence(doc);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0]["type"], "CityJSON");
  EXPECT_TRUE(lines[0]["CityObjects"].empty());
  EXPECT_TRUE(lines[0]["vertices"].empty());
  EXPECT_EQ(lines[0]["transform"], doc["transform"]);
  EXPECT_EQ(lines[1]["type"], "CityJSONFeature");
  EXPECT_EQ(lines[1]["id"], "house");
  EXPECT_EQ(lines[1]["CityObjects"].size(), 2u);  // house and its part
  EXPECT_EQ(lines[1]["CityObjects"]["house-part"]["parents"], json::array({"house"}));
  EXPECT_EQ(lines[1]["vertices"].size(), 6u);   // the two walls share an edge
  EXPECT_EQ(lines[2]["id"], "shed");
  EXPECT_EQ(lines[2]["vertices"].size(), 4u);
  // Our CityJSONSeq reader (written for users' files, independently of this writer) reads the sequence
  // into the mesh our CityJSON reader reads from the document.
  std::string text;
  for (const json& line : lines) text += line.dump() + "\n";
  const SemanticMesh whole = parse_cityjson(doc.dump(), "doc.city.json", taxonomy, 0);
  const SemanticMesh seq = parse_cityjson_seq(text, "doc.city.jsonl", taxonomy, 0);
  ASSERT_EQ(seq.entities.size(), whole.entities.size());
  for (size_t e = 0; e < whole.entities.size(); ++e) {
    EXPECT_EQ(seq.entities[e].source_id, whole.entities[e].source_id);
    EXPECT_EQ(seq.entities[e].level, whole.entities[e].level);
    EXPECT_EQ(seq.entities[e].class_id, whole.entities[e].class_id);
    EXPECT_EQ(seq.entities[e].parent, whole.entities[e].parent);
  }
  ASSERT_EQ(seq.triangles.size(), whole.triangles.size());
  for (size_t t = 0; t < whole.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(seq.vertices[seq.triangles[t][k]][a] + seq.origin[a], whole.vertices[whole.triangles[t][k]][a] + whole.origin[a], 1e-9);
}

TEST(CityObservations, AWallHalfInViewIsHalfCoveredAndItsWindowCountsForIt) {
  const WallWithWindow w;
  const CityObjects objects = city_objects(w.mesh, w.taxonomy);
  const std::vector<Vec3f> vertices = scene_vertices(w.mesh, CityTransform{});
  // One camera on the wall's normal at y = -5 looking along +y, its image covering x in [2, 4] of the wall
  // (z in [0, 3]): the right half of the wall, and none of the window (x in [1, 2]).
  Scene scene;
  SceneView view;
  view.name = "v.png";
  view.camera = {100, 100, 0, 0, 80, 120};  // u = 100 * (x - 2) / 5 on [0, 80): x in [2, 6)
  Mat3d R;  // camera x = world x, camera y = -world z, camera z = world y
  R.m[0][0] = 1, R.m[1][2] = -1, R.m[2][1] = 1;
  view.pose.R = R;
  view.pose.t = {-2, 3, 5};  // world (2, -5, 3) at the camera centre: image top-left looks at x = 2, z = 3
  scene.views.push_back(view);
  const auto dir = test::fresh_dir("cls_observations") / "v";
  std::filesystem::create_directories(dir);
  const int W = view.camera.width, H = view.camera.height;
  // The label maps as the raycaster would write them: the wall where the image shows it, at depth 5.
  std::vector<float> depth(static_cast<size_t>(W) * H, 0.0f);
  NpyArray object{"<i4", {H, W}, std::vector<uint8_t>(static_cast<size_t>(W) * H * 4)};
  int32_t* o = object.as<int32_t>();
  for (int v = 0; v < H; ++v)
    for (int u = 0; u < W; ++u) {
      const double x = 2 + (u + 0.5) * 5 / 100.0, z = 3 - (v + 0.5) * 5 / 100.0;
      const bool on_wall = x < 4 && z > 0;
      o[v * W + u] = on_wall ? 1 : -1;
      depth[static_cast<size_t>(v) * W + u] = on_wall ? 5.0f : 0.0f;
    }
  write_npy(dir / "object.npy", object);
  write_pfm(dir / "depth.pfm", depth, W, H);
  // Two Gaussians on the window and one on the wall.
  const std::vector<int32_t> gaussians = {2, 2, 1, -1};
  const auto seen = observe_city_objects(objects, w.mesh, vertices, scene, dir.parent_path(), gaussians);
  ASSERT_EQ(seen.size(), 3u);
  // The wall with the window in it: 12 m2; the visible part x in [2, 4]: 6 m2 (no window there).
  EXPECT_NEAR(seen[1].area, 12.0, 1e-9);
  EXPECT_NEAR(seen[1].covered_fraction(), 0.5, 0.01);
  EXPECT_NEAR(seen[2].area, 1.0, 1e-9);
  EXPECT_EQ(seen[2].seen_area, 0.0);
  EXPECT_NEAR(seen[0].area, 12.0, 1e-9);                  // the building: wall and window
  EXPECT_NEAR(seen[0].seen_area, seen[1].seen_area, 1e-9);
  EXPECT_EQ(seen[1].views, 1);
  EXPECT_EQ(seen[2].views, 0);
  EXPECT_EQ(seen[1].pixels, 40 * 60);                     // x in [2, 4) and z in (0, 3]: 40 x 60 pixels
  EXPECT_EQ(seen[0].pixels, seen[1].pixels);
  EXPECT_EQ(seen[2].gaussians, 2);
  EXPECT_EQ(seen[1].gaussians, 3);                        // its window's and its own
  EXPECT_EQ(seen[0].gaussians, 3);
}

TEST(OpeningProposals, WindowVotesOnAWallWithoutOneAreProposedAndAModelledWindowsRimIsNot) {
  const WallWithWindow w;
  const CityObjects objects = city_objects(w.mesh, w.taxonomy);
  const int window = w.taxonomy.find("window"), wall = w.taxonomy.find("wall");
  OpeningVotes votes(objects, w.mesh, {window, w.taxonomy.find("door")});
  const auto at = [&](double x, double z, double y = 0) {
    return Vec3d{x - w.mesh.origin[0], y - w.mesh.origin[1], z - w.mesh.origin[2]};
  };
  // Three views' votes every 5 cm over the wall: an unmodelled window at x in [2.6, 3.4], z in [1.2, 2.2]
  // votes window, so does a 10 cm rim around the modelled one (the field's blur), the rest votes wall.
  int64_t counted = 0;
  for (int view = 0; view < 3; ++view)
    for (double x = 0.025; x < 4; x += 0.05)
      for (double z = 0.025; z < 3; z += 0.05) {
        if (x > 1 && x < 2 && z > 1 && z < 2) {
          EXPECT_FALSE(votes.add(2, at(x, z), window));  // a modelled opening is no surface with a plane
          continue;
        }
        const bool unmodelled = x > 2.6 && x < 3.4 && z > 1.2 && z < 2.2;
        const bool rim = x > 0.9 && x < 2.1 && z > 0.9 && z < 2.1;
        counted += votes.add(1, at(x, z), unmodelled || rim ? window : wall);
      }
  EXPECT_GT(counted, 0);
  EXPECT_FALSE(votes.add(1, at(3.0, 1.5, 1.0), window));  // 1 m off the wall's plane
  EXPECT_FALSE(votes.add(0, at(3.0, 1.5), window));       // the building: no surface
  const auto proposals = votes.proposals();
  ASSERT_EQ(proposals.size(), 1u);
  const OpeningProposal& p = proposals[0];
  EXPECT_EQ(p.surface, 1);
  EXPECT_EQ(p.class_id, window);
  EXPECT_GT(p.confidence, 0.9);
  // The rectangle: the window's extent to within one cell (the grid is anchored at the wall's centroid).
  double x0 = 1e9, x1 = -1e9, z0 = 1e9, z1 = -1e9, y = 0;
  for (const Vec3d& c : p.corners) {
    x0 = std::min(x0, c.x + w.mesh.origin[0]), x1 = std::max(x1, c.x + w.mesh.origin[0]);
    z0 = std::min(z0, c.z + w.mesh.origin[2]), z1 = std::max(z1, c.z + w.mesh.origin[2]);
    y = std::max(y, std::abs(c.y + w.mesh.origin[1]));
  }
  const double cell = ProposalSettings{}.cell;
  EXPECT_NEAR(x0, 2.6, cell);
  EXPECT_NEAR(x1, 3.4, cell);
  EXPECT_NEAR(z0, 1.2, cell);
  EXPECT_NEAR(z1, 2.2, cell);
  EXPECT_NEAR(y, 0.0, 1e-9);  // on the wall's plane
  EXPECT_NEAR(p.width, x1 - x0, 1e-9);
  EXPECT_NEAR(p.height, z1 - z0, 1e-9);
  // Counter-clockwise about the wall's normal (-y): (c1 - c0) x (c3 - c0) points along -y.
  const Vec3d n = cross(p.corners[1] - p.corners[0], p.corners[3] - p.corners[0]);
  EXPECT_LT(n.y, 0);
  // With a margin of 0 around modelled openings, their rim is proposed too.
  ProposalSettings no_margin;
  no_margin.existing_margin = 0;
  OpeningVotes rim(objects, w.mesh, {window}, no_margin);
  for (double x = 0.025; x < 4; x += 0.05)
    for (double z = 0.025; z < 3; z += 0.05)
      for (int view = 0; view < 3; ++view) rim.add(1, at(x, z), x > 0.9 && x < 2.1 && z > 0.9 && z < 2.1 ? window : wall);
  EXPECT_EQ(rim.proposals().size(), 1u);
}

}  // namespace
}  // namespace cls
