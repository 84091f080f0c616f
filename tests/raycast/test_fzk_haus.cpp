// Label maps of the real FZK-Haus LoD3 model (CityGML 2.0 and 3.0 encodings) against the
// brute-force oracle, from oblique cameras on four sides, from above and from just below the eaves.
#include <gtest/gtest.h>

#include "citymodel/citygml_reader.h"
#include "raycast/label_maps.h"
#include "raycast/look_at.h"
#include "raycast/oracle.h"

namespace cls {
namespace {

class FzkHaus : public testing::TestWithParam<const char*> {};

TEST_P(FzkHaus, LabelMapsAgreeWithOracle) {
  const Taxonomy taxonomy = Taxonomy::builtin();
  const SemanticMesh mesh = read_citygml(std::string(CLS_TEST_DATA "/citygml/fzk-haus/") + GetParam(), taxonomy, 3);
  ASSERT_GT(mesh.num_triangles(), 200u);
  std::vector<Vec3f> vertices;
  for (const auto& p : mesh.vertices) vertices.push_back(Vec3f{float(p[0]), float(p[1]), float(p[2])});
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const auto& p : vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], double(p[k])), hi[k] = std::max(hi[k], double(p[k]));

  const std::vector<uint8_t> priority = opening_priority(mesh);
  const Raycaster rc(vertices, mesh.triangles, priority);
  const LabelTable table(mesh);
  const PinholeCamera cam{140, 140, 80, 60, 160, 120};
  const int window = taxonomy.find("window"), wall = taxonomy.find("wall"), building = taxonomy.find("building");
  ASSERT_GE(window, 0);

  for (const double elevation : {0.5, -0.1}) {
    for (int side = 0; side < 4; ++side) {
      const Pose pose = frame_box(lo, hi, cam, 0.3 + side * M_PI / 2, elevation, 1.3);
      std::vector<RayHit> hits;
      rc.cast_view(cam, pose, hits);
      LabelMaps got, want;
      table.fill(hits, cam.width, cam.height, got);
      const auto truth = test::oracle_view(vertices, mesh.triangles, priority, cam, pose);
      std::vector<RayHit> truth_hits(truth.size());
      for (size_t p = 0; p < truth.size(); ++p) truth_hits[p] = {float(truth[p].depth), truth[p].prim, 0, 0};
      table.fill(truth_hits, cam.width, cam.height, want);

      SCOPED_TRACE(testing::Message() << "side " << side << " elevation " << elevation);
      const size_t n = got.coverage.size();
      size_t windows = 0, covered = 0;
      for (size_t p = 0; p < n; ++p) {
        windows += want.level[0][p] == window + 1;
        covered += want.coverage[p] != 0;
        if (want.level[0][p] == window + 1) {  // a window pixel: wall at level 2, building at level 3
          EXPECT_EQ(want.level[1][p], wall + 1);
          EXPECT_EQ(want.level[2][p], building + 1);
        }
      }
      for (int l = 0; l < 3; ++l) {
        size_t agree = 0;
        for (size_t p = 0; p < n; ++p) agree += got.level[l][p] == want.level[l][p];
        EXPECT_GE(agree, 0.999 * n) << "level " << l + 1;
      }
      EXPECT_GT(covered, n / 3);  // the house fills a good part of the frame
      if (elevation > 0) EXPECT_GT(windows, 30u);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Encodings, FzkHaus,
                         testing::Values("fzk_haus_lod3_v2.gml", "FZK-Haus-LoD3-KIT-IAI-KHH-B36-V1__v3.gml"));

}  // namespace
}  // namespace cls
