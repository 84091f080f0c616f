// run --align's decisions (pipeline/city_alignment.h) on FZK-Haus with hand-placed points.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/run_layout.h"
#include "pipeline/city_alignment.h"
#include "raycast/closest_point.h"

namespace cls {
namespace {
namespace fs = std::filesystem;

const std::string kFzk = CLS_TEST_DATA "/citygml/fzk-haus/fzk_haus_lod3_v2.gml";

struct Fixture {
  fs::path out = fs::temp_directory_path() / ("cls_city_alignment_" + std::to_string(::getpid()));
  SceneCityModel city = load_scene_city_model(kFzk, "", CityModelOptions{}, "test");
  Fixture() { fs::remove_all(out); }
  ~Fixture() { fs::remove_all(out); }
  // The triangles' centroids, shifted by `offset`: the model's surface, off by a known translation.
  Scene points(Vec3d offset) const {
    Scene s;
    s.root = "hand-made";
    for (const auto& t : city.mesh.triangles) {
      const Vec3d c = (1.0 / 3) * (cast<double>(city.vertices[t[0]]) + cast<double>(city.vertices[t[1]]) +
                                   cast<double>(city.vertices[t[2]]));
      SparsePoint p;
      p.xyz = c + offset;
      s.points.push_back(p);
    }
    return s;
  }
};

TEST(CityAlignment, AutoAppliesAHelpfulRefinementAndKeepsAnExactTransform) {
  Fixture f;
  SceneCityModel exact = f.city;
  const CityAlignment kept = align_city_model(f.points({0, 0, 0}), exact, "auto", 0.5,
                                              RunLayout(f.out).align_transform());
  EXPECT_FALSE(kept.applied);
  EXPECT_NE(kept.record["reason"].get<std::string>().find("at most"), std::string::npos) << kept.record.dump();
  EXPECT_FALSE(fs::exists(RunLayout(f.out).align_transform()));

  SceneCityModel moved = f.city;
  const CityAlignment applied = align_city_model(f.points({0.4, -0.3, 0.2}), moved, "auto", 0.5,
                                                 RunLayout(f.out).align_transform());
  ASSERT_TRUE(applied.applied) << applied.record.dump();
  EXPECT_TRUE(fs::exists(applied.transform));
  // The model now sits on the shifted points: its translation is the shift.
  const Vec3d t = moved.transform.translation() - f.city.transform.translation();
  EXPECT_NEAR(t.x, 0.4, 0.01);
  EXPECT_NEAR(t.y, -0.3, 0.01);
  EXPECT_NEAR(t.z, 0.2, 0.01);
  // A later run that does not use it leaves no stale file behind.
  SceneCityModel again = f.city;
  EXPECT_FALSE(align_city_model(f.points({0.4, -0.3, 0.2}), again, "off", 0.5, RunLayout(f.out).align_transform()).applied);
  EXPECT_FALSE(fs::exists(applied.transform));
}

// An error below the check's distance, with most points off the model (terrain and clutter the model
// lacks, 2-4 m below it, which the correction moves it away from): no point crosses 0.5 m and the median
// grows (the first rule kept the given transform here), but the refinement puts the model's points onto
// its surfaces, and auto applies it.
TEST(CityAlignment, AutoAppliesASmallCorrectionAmongPointsOffTheModel) {
  Fixture f;
  Scene scene = f.points({0.15, -0.15, 0.1});
  const size_t on_model = scene.points.size();
  Vec3d lo{INFINITY, INFINITY, INFINITY}, hi = -1.0 * lo;
  for (const auto& v : f.city.vertices)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], double(v[k])), hi[k] = std::max(hi[k], double(v[k]));
  for (size_t i = 0; i < 2 * on_model; ++i) {  // a sheet 2-4 m below the ground surface
    SparsePoint p;
    const double u = (i % 97) / 97.0, w = (i % 89) / 89.0;
    p.xyz = {lo.x + u * (hi.x - lo.x), lo.y + w * (hi.y - lo.y), lo.z - 2 - 2 * u};
    scene.points.push_back(p);
  }
  SceneCityModel moved = f.city;
  const CityAlignment a = align_city_model(scene, moved, "auto", 0.5, RunLayout(f.out).align_transform());
  ASSERT_TRUE(a.applied) << a.record.dump();
  EXPECT_GT(a.record["after"]["fraction_within_finest"].get<double>(),
            a.record["before"]["fraction_within_finest"].get<double>() + 0.2);
  const Vec3d t = moved.transform.translation() - f.city.transform.translation();
  EXPECT_NEAR(t.x, 0.15, 0.01);
  EXPECT_NEAR(t.y, -0.15, 0.01);
  EXPECT_NEAR(t.z, 0.1, 0.01);
}

TEST(CityAlignment, NoPointsIsAWarningForAutoAndAnErrorForRefine) {
  Fixture f;
  Scene empty;
  empty.root = "empty-scene";
  SceneCityModel city = f.city;
  EXPECT_FALSE(align_city_model(empty, city, "auto", 0.5, RunLayout(f.out).align_transform()).applied);
  EXPECT_THROW(align_city_model(empty, city, "refine", 0.5, RunLayout(f.out).align_transform()), Error);
}

}  // namespace
}  // namespace cls
